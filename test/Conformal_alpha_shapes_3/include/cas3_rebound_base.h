// Whether a base class of the triangulation is rebound to it, for the tests
// of the vertex and cell bases.
#ifndef CAS3_REBOUND_BASE_H
#define CAS3_REBOUND_BASE_H

#include <type_traits>

namespace cas3_test {

template <template <class, class> class Base, class Kernel>
struct Derives_from
{
  template <class Below>
  static std::true_type test(const Base<Kernel, Below>*);
  static std::false_type test(...);
};

// Whether `Element` (a triangulation's Vertex or Cell) derives from
// `Base<Kernel, B>` for some base B, whose bottom is the triangulation's
// own `Bottom`: the rebind reached every layer, so the handles are the
// triangulation's.
template <template <class, class> class Base, class Kernel, class Element, class Bottom>
constexpr bool is_rebound()
{
  return decltype(Derives_from<Base, Kernel>::test(static_cast<const Element*>(nullptr)))::value
         && std::is_base_of<Bottom, Element>::value;
}

} // namespace cas3_test

#endif // CAS3_REBOUND_BASE_H
