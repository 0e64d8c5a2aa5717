// The output directory of the conformal_curvature program as a transaction:
// files are written into a private temporary directory and moved into the
// output directory only when the whole run succeeded, so that a failed run
// leaves the output directory as it was: no partial or hidden files, and no
// directory when the run created it. A fatal signal (a crash, an interrupt)
// removes the temporary files and the created directories too. The output
// directory is created and probed for writing before any work starts.
#ifndef CAS3_OUTPUT_TRANSACTION_H
#define CAS3_OUTPUT_TRANSACTION_H

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include <unistd.h>

namespace cas3 {

// A file or directory that cannot be written; what() is one line.
struct Output_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

namespace output_cleanup {

// What the fatal-signal handler removes, in fixed arrays: a handler may
// only call async-signal-safe functions, so it cannot allocate or format.
inline char temporary_dir[4096] = "";
inline char files[64][4096];
inline volatile std::sig_atomic_t number_of_files = 0;
inline char created_dirs[16][4096];  // the directories this run created, deepest first
inline volatile std::sig_atomic_t number_of_created_dirs = 0;

extern "C" inline void on_fatal_signal(int sig)
{
  for(int i = 0; i < number_of_files; ++i)
    ::unlink(files[i]);
  if(temporary_dir[0])
    ::rmdir(temporary_dir);
  for(int i = 0; i < number_of_created_dirs; ++i)
    ::rmdir(created_dirs[i]);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

inline void copy(char* to, const std::string& from)
{
  std::strncpy(to, from.c_str(), 4095);
  to[4095] = 0;
}

} // namespace output_cleanup

class Output_transaction
{
public:
  explicit Output_transaction(const std::string& dir) : m_name(dir), m_dir(dir)
  {
    namespace fs = std::filesystem;
    std::error_code error;
    const bool existed = fs::exists(m_dir, error);
    if(existed && !fs::is_directory(m_dir, error))
      throw Output_error("cannot create the output directory " + dir + ": a file of that name exists");
    if(!existed)
    {
      // remember the levels we create, to remove them on failure
      std::vector<fs::path> created;
      for(fs::path p = fs::absolute(m_dir, error); !p.empty() && !fs::exists(p, error); p = p.parent_path())
      {
        created.push_back(p);
        if(p == p.parent_path())
          break;
      }
      fs::create_directories(m_dir, error);
      if(!fs::is_directory(m_dir, error))
        throw Output_error("cannot create the output directory " + dir);
      m_created = created.empty() ? fs::path() : created.back();
      for(std::size_t i = 0; i < created.size() && i < 16; ++i)
        output_cleanup::copy(output_cleanup::created_dirs[i], created[i].string());
      output_cleanup::number_of_created_dirs = int((std::min)(created.size(), std::size_t(16)));
    }
    // probe: can we create and rename files there?
    const fs::path probe = m_dir / (".conformal_curvature_probe_" + std::to_string(::getpid()));
    {
      std::ofstream out(probe);
      out << "probe";
      out.close();
      if(!out)
      {
        fs::remove(probe, error);
        remove_created();
        throw Output_error("cannot write into the output directory " + dir);
      }
    }
    fs::remove(probe, error);

    std::string templ = (fs::temp_directory_path(error) / "conformal_curvature_XXXXXX").string();
    if(::mkdtemp(&templ[0]) == nullptr)
    {
      remove_created();
      throw Output_error("cannot create a temporary directory in " + fs::temp_directory_path(error).string());
    }
    m_temporary = templ;
    output_cleanup::copy(output_cleanup::temporary_dir, templ);
    for(int sig : {SIGSEGV, SIGABRT, SIGFPE, SIGBUS, SIGILL, SIGINT, SIGTERM})
      std::signal(sig, output_cleanup::on_fatal_signal);
  }
  Output_transaction(const Output_transaction&) = delete;
  Output_transaction& operator=(const Output_transaction&) = delete;
  ~Output_transaction()
  {
    std::error_code ignored;
    output_cleanup::number_of_files = 0;
    output_cleanup::temporary_dir[0] = 0;
    std::filesystem::remove_all(m_temporary, ignored);
    if(!m_committed)
      remove_created();
    output_cleanup::number_of_created_dirs = 0;
  }

  // A new file `name` of the output, written in the temporary directory.
  std::ofstream open(const std::string& name, bool binary)
  {
    m_files.push_back(name);
    if(output_cleanup::number_of_files < 64)
    {
      output_cleanup::copy(output_cleanup::files[output_cleanup::number_of_files], (m_temporary / name).string());
      output_cleanup::number_of_files = output_cleanup::number_of_files + 1;
    }
    std::ofstream out(m_temporary / name, binary ? std::ios::binary : std::ios::out);
    if(!out)
      throw Output_error("cannot write a temporary file into " + m_temporary.string());
    return out;
  }

  // Throws when a write into `out` (a file from open()) has failed.
  void check(const std::ofstream& out) const
  {
    if(!out)
      throw Output_error("cannot write into the output directory " + m_name);
  }

  // Closes `out` (a file from open()); throws when it was not all written.
  void close(std::ofstream& out) const
  {
    out.close();
    check(out);
  }

  // Moves the files into the output directory.
  void commit()
  {
    for(const auto& f : m_files)
    {
      std::error_code error;
      std::filesystem::rename(m_temporary / f, m_dir / f, error);
      if(error)  // another file system: copy
      {
        std::filesystem::copy_file(m_temporary / f, m_dir / f, std::filesystem::copy_options::overwrite_existing,
                                   error);
        if(error)
          throw Output_error("cannot write into the output directory " + m_name);
      }
    }
    m_committed = true;
  }

private:
  void remove_created()
  {
    std::error_code ignored;
    if(!m_created.empty())
      std::filesystem::remove_all(m_created, ignored);
    m_created.clear();
  }
  std::string m_name;  // as given, for the messages
  std::filesystem::path m_dir, m_temporary, m_created;
  std::vector<std::string> m_files;
  bool m_committed = false;
};

} // namespace cas3

#endif // CAS3_OUTPUT_TRANSACTION_H
