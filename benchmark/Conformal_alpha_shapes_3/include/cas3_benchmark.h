// Timing and memory helpers shared by the benchmark programs (Linux only).
#ifndef CAS3_BENCHMARK_H
#define CAS3_BENCHMARK_H

#include <malloc.h>

#include <chrono>
#include <fstream>
#include <string>

namespace cas3_benchmark {

inline double kib_field(const char* field)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  const std::string key = std::string(field) + ":";
  while(std::getline(status, line))
    if(line.compare(0, key.size(), key) == 0)
      return std::stod(line.substr(key.size()));
  return 0;
}

// Measures wall time and the peak resident memory a phase adds: the kernel's
// high-water mark is reset at the start (clear_refs 5), and freed heap is
// returned first so that an earlier phase's memory is not reused unseen.
class Phase
{
public:
  Phase()
  {
    malloc_trim(0);
    std::ofstream("/proc/self/clear_refs") << "5";
    m_base_kib = kib_field("VmRSS");
    m_start = std::chrono::steady_clock::now();
  }
  double seconds() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
  }
  double peak_mib() const { return (kib_field("VmHWM") - m_base_kib) / 1024.0; }

private:
  double m_base_kib;
  std::chrono::steady_clock::time_point m_start;
};

} // namespace cas3_benchmark

#endif // CAS3_BENCHMARK_H
