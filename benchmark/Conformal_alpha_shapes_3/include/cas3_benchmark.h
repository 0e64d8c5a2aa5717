// Timing and memory helpers shared by the benchmark programs (Linux only).
#ifndef CAS3_BENCHMARK_H
#define CAS3_BENCHMARK_H

#include <malloc.h>

#include <CGAL/IO/read_points.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

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

// The command line of the benchmarks: [--sizes N,N,...] [--flag ...] [FILE...].
struct Arguments
{
  std::vector<std::size_t> sizes = {100000, 1000000};
  std::vector<std::string> files;  // default: the bundled bunny
  std::vector<std::string> flags;
  bool has(const std::string& flag) const
  {
    for(const std::string& f : flags)
      if(f == flag) return true;
    return false;
  }
};

inline Arguments parse_arguments(int argc, char* argv[])
{
  Arguments a;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if(arg == "--sizes" && i + 1 < argc)
    {
      a.sizes.clear();
      std::stringstream list(argv[++i]);
      std::string item;
      while(std::getline(list, item, ',')) a.sizes.push_back(std::stoul(item));
    }
    else if(arg.rfind("--", 0) == 0) a.flags.push_back(arg);
    else a.files.push_back(arg);
  }
  if(a.files.empty()) a.files.push_back(CGAL_CAS3_DEFAULT_INPUT);
  return a;
}

// Calls run(file name, points) for each file; false at the first unreadable one.
template <class Point, class Run>
bool for_each_point_file(const std::vector<std::string>& files, Run run)
{
  for(const std::string& f : files)
  {
    std::vector<Point> points;
    if(!CGAL::IO::read_points(f, std::back_inserter(points)) || points.empty())
    {
      std::cerr << "cannot read " << f << "\n";
      return false;
    }
    run(f.substr(f.find_last_of('/') + 1), points);
  }
  return true;
}

} // namespace cas3_benchmark

#endif // CAS3_BENCHMARK_H
