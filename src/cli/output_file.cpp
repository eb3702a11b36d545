#include "output_file.h"

#include <cerrno>
#include <cstring>

namespace riser_sim {
namespace cli {

OutputFile::~OutputFile() {
  if (f_ && !is_stdout_) std::fclose(f_);  // only on early returns: callers close() to see errors
}

bool OutputFile::open(const std::string& option, const std::string& path) {
  name_ = option + ": write to '" + path + "'";
  f_ = std::fopen(path.c_str(), "w");
  if (!f_) error_ = option + ": cannot open '" + path + "': " + std::strerror(errno);
  return f_ != nullptr;
}

void OutputFile::useStdout() {
  f_ = stdout;
  is_stdout_ = true;
  name_ = "write to stdout";
}

void OutputFile::setError(int err) {
  if (error_.empty()) error_ = name_ + " failed" + (err ? std::string(": ") + std::strerror(err) : "");
}

bool OutputFile::ok() {
  // errno is the failed write's: nothing but stdio calls on this stream run between it and this check.
  if (f_ && std::ferror(f_)) setError(errno);
  return error_.empty();
}

bool OutputFile::close() {
  if (!f_) return error_.empty();
  ok();
  errno = 0;
  if (std::fflush(f_) != 0 || std::ferror(f_)) setError(errno);
  if (!is_stdout_) {
    errno = 0;
    if (std::fclose(f_) != 0) setError(errno);  // e.g. a network file system reports at close
  }
  f_ = nullptr;
  return error_.empty();
}

}  // namespace cli
}  // namespace riser_sim
