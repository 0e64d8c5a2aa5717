// Timing and memory helpers shared by the benchmark programs (Linux only),
// and the provenance lines that head their CSV files.
#ifndef CAS3_BENCHMARK_H
#define CAS3_BENCHMARK_H

#include <malloc.h>

#include <CGAL/IO/read_points.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
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

// The command line of the benchmarks: [--sizes N,N,...] [--csv FILE] [--flag ...] [FILE...].
struct Arguments
{
  std::vector<std::size_t> sizes = {100000, 1000000};
  std::string csv;  // where to write the results as CSV, or empty
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
    else if(arg == "--csv" && i + 1 < argc) a.csv = argv[++i];
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

// The first line of `command`'s output, or "unknown" when it gives none.
inline std::string first_output_line(const std::string& command)
{
  std::string line;
  if(FILE* pipe = ::popen(command.c_str(), "r"))
  {
    char buffer[512];
    if(std::fgets(buffer, sizeof buffer, pipe))
      line = buffer;
    ::pclose(pipe);
  }
  while(!line.empty() && (line.back() == '\n' || line.back() == '\r'))
    line.pop_back();
  return line.empty() ? "unknown" : line;
}

// The value of the first line of /proc/`file` that starts with `key`.
inline std::string proc_field(const char* file, const std::string& key)
{
  std::ifstream in(std::string("/proc/") + file);
  std::string line;
  while(std::getline(in, line))
    if(line.compare(0, key.size(), key) == 0)
    {
      const std::size_t start = line.find_first_not_of(" \t:", key.size());
      return start == std::string::npos ? std::string() : line.substr(start);
    }
  return "unknown";
}

// The lines `# commit`, `# machine` and `# command` that head a benchmark's
// CSV file, so that a table made from it says what was measured where; the
// commit is that of the source tree the benchmark was built from, at run time.
inline void write_csv_provenance(std::ostream& out, int argc, char* argv[])
{
#ifdef CAS3_SOURCE_DIR
  out << "# commit " << first_output_line("git -C '" CAS3_SOURCE_DIR "' describe --always --dirty --tags 2>/dev/null")
      << '\n';
#else
  out << "# commit unknown\n";
#endif
  out << "# machine " << proc_field("cpuinfo", "model name") << ", " << std::thread::hardware_concurrency()
      << " cores, " << proc_field("meminfo", "MemTotal") << '\n';
  out << "# command";
  for(int i = 0; i < argc; ++i)
    out << ' ' << argv[i];
  out << '\n';
}

// `s` as a CSV field: quoted when it holds a comma, a quote or a line break.
inline std::string csv_field(const std::string& s)
{
  if(s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for(char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// The CSV file `path` headed by the provenance lines and `columns`; closed
// (writes nothing) when `path` is empty: no file was asked for.
inline std::ofstream open_csv(const std::string& path, int argc, char* argv[], const std::string& columns)
{
  std::ofstream out;
  if(path.empty())
    return out;
  out.open(path);
  if(!out)
  {
    std::cerr << "cannot write " << path << "\n";
    std::exit(EXIT_FAILURE);
  }
  write_csv_provenance(out, argc, argv);
  out << columns << '\n';
  return out;
}

} // namespace cas3_benchmark

#endif // CAS3_BENCHMARK_H
