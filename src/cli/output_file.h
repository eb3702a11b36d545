// An output of riser_sim_cli (a file or stdout) whose write errors are never lost: every batch of
// writes is followed by ok(), the end by close(); both name the output in error().
#pragma once
#include <cstdio>
#include <string>

namespace riser_sim {
namespace cli {

class OutputFile {
 public:
  OutputFile() = default;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile();

  // Opens PATH for writing ("w"); OPTION names it in messages ("--csv"). False: see error().
  bool open(const std::string& option, const std::string& path);
  // Wraps stdout (not closed, only flushed).
  void useStdout();

  bool isOpen() const { return f_ != nullptr; }
  std::FILE* get() const { return f_; }
  // False once any write so far failed (the stream's error flag); sets error() the first time.
  bool ok();
  // Flushes and closes (stdout: flushes). False if this or any earlier write failed.
  bool close();
  // "--csv: write to 'out.csv' failed: No space left on device"; empty while nothing failed.
  const std::string& error() const { return error_; }

 private:
  void setError(int err);

  std::FILE* f_ = nullptr;
  bool is_stdout_ = false;
  std::string name_, error_;
};

}  // namespace cli
}  // namespace riser_sim
