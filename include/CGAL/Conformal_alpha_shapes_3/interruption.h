// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERRUPTION_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERRUPTION_H

#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <thread>
#include <utility>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/*!
\ingroup PkgConformalAlphaShapes3Multiscale
Thrown by the package's long computations when the interruption check of
the thread that started them (`Scoped_interruption_check`) asks them to stop.
*/
struct Interrupted : std::exception
{
  const char* what() const noexcept override { return "Conformal_alpha_shapes_3: interrupted"; }
};

namespace internal {

// The check installed on this thread, or null.
inline const std::function<bool()>*& interruption_check_of_this_thread()
{
  thread_local const std::function<bool()>* check = nullptr;
  return check;
}

} // namespace internal

/*!
\ingroup PkgConformalAlphaShapes3Multiscale

While an object of this class lives, the package's long computations
started on the calling thread (the construction of a
`Conformal_alpha_shape_3`, the advancing front and the surfaces cut from
it, the per-point and per-vertex passes of denoising, curvature and
transfer) call `check()` on that thread every 20 ms or so of their work, and throw `Interrupted` as soon as it returns
`true`, leaving the objects they were filling empty or unspecified (a shape
being built is cleared). For front ends that must stay responsive: the
Python module stops on Ctrl-C this way. Without a check the computations
run as before, with the same results; with one, the results are the same
unless interrupted. Objects of this class nest; the innermost check is used.
*/
class Scoped_interruption_check
{
public:
  explicit Scoped_interruption_check(std::function<bool()> check)
    : m_check(std::move(check)), m_outer(internal::interruption_check_of_this_thread())
  {
    internal::interruption_check_of_this_thread() = &m_check;
  }
  ~Scoped_interruption_check() { internal::interruption_check_of_this_thread() = m_outer; }
  Scoped_interruption_check(const Scoped_interruption_check&) = delete;
  Scoped_interruption_check& operator=(const Scoped_interruption_check&) = delete;

private:
  std::function<bool()> m_check;
  const std::function<bool()>* m_outer;
};

namespace internal {

// A computation's link to the check of the thread that starts it: any
// thread asks `stop_requested()` often; only the starting thread calls the
// check, at most every 20 ms, since a check may need that thread (Python's
// signals are seen on the main thread only).
class Interruption_point
{
public:
  Interruption_point()
    : m_check(interruption_check_of_this_thread()), m_thread(std::this_thread::get_id()),
      m_next(std::chrono::steady_clock::now())
  {}

  bool stop_requested()
  {
    if(m_check == nullptr)
      return false;
    if(m_stop.load(std::memory_order_relaxed))
      return true;
    if(std::this_thread::get_id() != m_thread)
      return false;
    const auto now = std::chrono::steady_clock::now();
    if(now < m_next)
      return false;
    m_next = now + std::chrono::milliseconds(20);
    if((*m_check)())
      m_stop.store(true, std::memory_order_relaxed);
    return m_stop.load(std::memory_order_relaxed);
  }

  void throw_if_stopped()
  {
    if(stop_requested())
      throw Interrupted();
  }

  // After a loop whose threads skipped their work once a stop was requested.
  void throw_if_stop_was_requested() const
  {
    if(m_stop.load(std::memory_order_relaxed))
      throw Interrupted();
  }

private:
  const std::function<bool()>* m_check;
  std::thread::id m_thread;
  std::chrono::steady_clock::time_point m_next;
  std::atomic<bool> m_stop{false};
};

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERRUPTION_H
