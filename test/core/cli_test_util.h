// Shared by the CLI's end-to-end tests: runs the built binary (RISER_SIM_CLI_BINARY, set by
// cmake/cli.cmake), reads its outputs, parses its summary and CSV.
#pragma once
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#ifndef RISER_SIM_CLI_BINARY
#error "RISER_SIM_CLI_BINARY must be defined (cmake/cli.cmake)"
#endif

// RISER_SIM_ASAN: built with AddressSanitizer. gcc defines __SANITIZE_ADDRESS__; clang-14 (the sanitizer
// build's compiler, tools/test_sanitize.sh) does not, it has __has_feature(address_sanitizer).
#if defined(__SANITIZE_ADDRESS__)
#define RISER_SIM_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RISER_SIM_ASAN 1
#endif
#endif

namespace cli_test {

inline const std::string kScenes = std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/";
inline const std::string kChain = kScenes + "hanging_chain.yaml";

inline std::string tempPath(const std::string& name) {
  return testing::TempDir() + "/riser_sim_test_cli_" + std::to_string(getpid()) + "_" + name;
}

// Writes a scene to a temporary file; returns its path.
inline std::string writeScene(const std::string& name, const std::string& text) {
  const std::string path = tempPath(name + ".yaml");
  std::ofstream(path) << text;
  return path;
}

inline std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct CliRun {
  int code = -1;
  std::string out, err;
};

// Runs the CLI with `args` (already shell-quoted where needed; may redirect stdout); `prefix` runs first
// in the same shell (e.g. ulimit).
inline CliRun runCli(const std::string& args, const std::string& prefix = "") {
  const std::string err_path = tempPath("stderr.txt");
  const std::string cmd = prefix + std::string(RISER_SIM_CLI_BINARY) + " " + args + " 2>" + err_path;
  CliRun r;
  std::FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof(buf), p)) > 0) r.out.append(buf, n);
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = readFile(err_path);
  std::filesystem::remove(err_path);
  return r;
}

// Minimal parser for the summary: one flat JSON object of numbers, strings, booleans and null.
// Values are kept as their JSON text (strings unquoted). Returns false on anything else.
inline bool parseFlatJson(const std::string& line, std::map<std::string, std::string>& out) {
  size_t i = 0;
  const auto skip = [&] {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
  };
  const auto str = [&](std::string& s) {
    if (line[i] != '"') return false;
    for (++i; i < line.size() && line[i] != '"'; ++i) {
      if (line[i] == '\\') ++i;
      s += line[i];
    }
    return i++ < line.size();
  };
  skip();
  if (i >= line.size() || line[i++] != '{') return false;
  for (;;) {
    skip();
    std::string key, value;
    if (!str(key)) return false;
    skip();
    if (line[i++] != ':') return false;
    skip();
    if (line[i] == '"') {
      if (!str(value)) return false;
    } else {
      while (i < line.size() && line[i] != ',' && line[i] != '}') value += line[i++];
      if (value != "true" && value != "false" && value != "null") {
        char* end = nullptr;
        std::strtod(value.c_str(), &end);
        if (value.empty() || *end != '\0') return false;
      }
    }
    out[key] = value;
    skip();
    if (i >= line.size()) return false;
    if (line[i] == '}') return true;
    if (line[i++] != ',') return false;
  }
}

// Parses CSV rows into numbers; fails the test on a non-numeric or non-finite field.
inline std::vector<std::vector<double>> csvRows(const std::string& text, std::string& header) {
  std::istringstream in(text);
  std::getline(in, header);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream ls(line);
    std::string field;
    while (std::getline(ls, field, ',')) {
      char* end = nullptr;
      const double v = std::strtod(field.c_str(), &end);
      EXPECT_TRUE(!field.empty() && *end == '\0' && std::isfinite(v)) << "bad field '" << field << "' in " << line;
      row.push_back(v);
    }
    rows.push_back(row);
  }
  return rows;
}

// The --summary line of a run as key -> value text; num() one number of it (NaN and a failure when absent).
inline std::map<std::string, std::string> summary(const CliRun& r) {
  std::map<std::string, std::string> j;
  EXPECT_TRUE(parseFlatJson(r.out, j)) << r.out;
  return j;
}
inline double num(std::map<std::string, std::string>& j, const std::string& key) {
  EXPECT_EQ(j.count(key), 1u) << "summary lacks " << key;
  return j.count(key) ? std::stod(j[key]) : NAN;
}

// The CSV columns of every scene (a planar scene in x-z, z up); column indices below.
const char* kHeader =
    "t,x_top,y_top,z_top,x_end,y_end,z_end,top_fx,top_fy,top_fz,bottom_fx,bottom_fy,bottom_fz,top_mx,top_my,top_mz,"
    "bottom_mx,bottom_my,bottom_mz,tension_top,tension_max,energy,work,energy_drift,constraint_error";
constexpr size_t kColumns = 25, kXEnd = 4, kYEnd = 5, kZEnd = 6, kTensionTop = 19, kDrift = 23;

}  // namespace cli_test
