// A markdown table a bench prints to stdout and writes to <tables>/<name>.md (out/bench/tables, or
// RISER_SIM_BENCH_TABLES) for bench/update_docs.py: the format of bench/bench_tables.py, a line naming the
// command, the machine, the date and the revision (RISER_SIM_BENCH_STAMP when run_all.sh sets it), a
// blank line, the table.
#pragma once
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace riser_sim {
namespace bench {

inline std::string commandLine(int argc, char** argv) {
  std::string s = std::filesystem::path(argv[0]).filename().string();
  for (int i = 1; i < argc; ++i) s += std::string(" ") + argv[i];
  return s;
}

// "<CPU model> (<k> CPUs), <date>, <git describe>".
inline std::string stamp() {
  if (const char* env = std::getenv("RISER_SIM_BENCH_STAMP"); env && *env) return env;
  std::string model = "unknown CPU", line;
  std::ifstream cpu("/proc/cpuinfo");
  while (std::getline(cpu, line))
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  char date[16];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d", std::localtime(&now));
  // The revision of the working directory's repository, else of the one holding the executable (.ws/devel/...).
  std::string rev;
  std::error_code ec;
  const std::string exe_dir = std::filesystem::read_symlink("/proc/self/exe", ec).parent_path().string();
  for (const std::string& dir : {std::string("."), exe_dir}) {
    if (dir.empty() || dir.find('\'') != std::string::npos) continue;
    const std::string cmd = "git -C '" + dir + "' describe --always --dirty --tags 2>/dev/null";
    if (std::FILE* p = popen(cmd.c_str(), "r")) {
      char buf[128];
      while (std::fgets(buf, sizeof buf, p)) rev += buf;
      pclose(p);
    }
    while (!rev.empty() && (rev.back() == '\n' || rev.back() == ' ')) rev.pop_back();
    if (!rev.empty()) break;
  }
  return model + " (" + std::to_string(std::thread::hardware_concurrency()) + " CPUs), " + date + ", " +
         (rev.empty() ? "unknown revision" : rev);
}

class MarkdownTable {
 public:
  // name: [a-z0-9_] (the marker <!-- bench:name --> in docs/benchmarks.md).
  MarkdownTable(std::string name, std::string command) : name_(std::move(name)), command_(std::move(command)) {}

  // printf to stdout, and the same text kept for the file.
  void printf(const char* fmt, ...) __attribute__((format(printf, 2, 3))) {
    va_list a, b;
    va_start(a, fmt);
    va_copy(b, a);
    const int len = std::vsnprintf(nullptr, 0, fmt, a);
    va_end(a);
    std::string s(len > 0 ? size_t(len) : 0, '\0');
    if (len > 0) std::vsnprintf(s.data(), s.size() + 1, fmt, b);
    va_end(b);
    std::fputs(s.c_str(), stdout);
    text_ += s;
  }

  // Writes the file; false (and a message on stderr) when it cannot.
  bool write() const {
    const char* env = std::getenv("RISER_SIM_BENCH_TABLES");
    const std::filesystem::path dir = env && *env ? env : "out/bench/tables";
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    std::string body = text_;
    while (!body.empty() && (body.front() == '\n')) body.erase(0, 1);
    while (!body.empty() && (body.back() == '\n' || body.back() == ' ')) body.pop_back();
    const std::filesystem::path path = dir / (name_ + ".md");
    std::ofstream f(path);
    f << "Made by `" << command_ << "` on " << stamp() << ".\n\n" << body << "\n";
    if (!f) {
      std::fprintf(stderr, "cannot write the table %s\n", path.c_str());
      return false;
    }
    std::printf("wrote %s\n", path.c_str());
    return true;
  }

 private:
  std::string name_, command_, text_;
};

}  // namespace bench
}  // namespace riser_sim
