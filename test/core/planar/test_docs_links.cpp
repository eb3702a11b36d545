// The manual stays true to the tree: every file and code symbol that docs/architecture.md names in
// backticks exists, and every relative link in README.md and docs/*.md reaches a file (and its heading).
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = RISER_SIM_SOURCE_DIR;

std::string readFile(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Text outside ``` fences.
std::string prose(const std::string& md) {
  std::string out;
  std::istringstream in(md);
  std::string line;
  bool fenced = false;
  while (std::getline(in, line)) {
    if (line.rfind("```", 0) == 0) {
      fenced = !fenced;
      continue;
    }
    if (!fenced) out += line + "\n";
  }
  return out;
}

// GitHub's heading anchor: lower case, punctuation dropped (but '-' and '_'), spaces to '-'.
std::string slug(const std::string& heading) {
  std::string s;
  for (unsigned char c : heading) {
    if (std::isalnum(c) || c == '-' || c == '_')
      s += static_cast<char>(std::tolower(c));
    else if (c == ' ')
      s += '-';
    else if (c >= 0x80)
      s += static_cast<char>(c);  // UTF-8 letters stay
  }
  return s;
}

std::set<std::string> anchors(const fs::path& md) {
  std::set<std::string> out;
  std::istringstream in(readFile(md));
  std::string line;
  bool fenced = false;
  while (std::getline(in, line)) {
    if (line.rfind("```", 0) == 0) fenced = !fenced;
    if (fenced || line.empty() || line[0] != '#') continue;
    const size_t text = line.find_first_not_of('#');
    if (text == std::string::npos) continue;
    std::string h = line.substr(text);
    h.erase(0, h.find_first_not_of(' '));
    std::string plain;  // `code` and [links](x) keep their text only
    for (size_t k = 0; k < h.size(); ++k) {
      if (h[k] == '`' || h[k] == '*') continue;
      plain += h[k];
    }
    out.insert(slug(plain));
  }
  return out;
}

// The identifiers of every source and header of the package: all of them, and those that are declared or
// called as free or own functions (followed by '(' and not reached through '.' or '->').
struct Identifiers {
  std::set<std::string> any, functions;
};

const Identifiers& identifiers() {
  static const Identifiers ids = [] {
    Identifiers out;
    std::vector<fs::path> files = {kRoot / "CMakeLists.txt", kRoot / "Makefile"};
    for (const char* dir : {"include", "src", "test", "bench", "scripts", "cmake", "launch", "config"})
      for (const auto& e : fs::recursive_directory_iterator(kRoot / dir))
        if (e.is_regular_file()) files.push_back(e.path());
    for (const fs::path& f : files) {
      const std::string s = readFile(f);
      const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
      for (size_t k = 0; k < s.size();) {
        if (!word(s[k]) || (k > 0 && word(s[k - 1]))) {
          ++k;
          continue;
        }
        size_t e = k;
        while (e < s.size() && word(s[e])) ++e;
        const std::string id = s.substr(k, e - k);
        out.any.insert(id);
        size_t next = e;
        while (next < s.size() && s[next] == ' ') ++next;
        size_t prev = k;
        while (prev > 0 && s[prev - 1] == ' ') --prev;
        const char before = prev > 0 ? s[prev - 1] : '\n';
        if (next < s.size() && s[next] == '(' && before != '.' && before != '>') out.functions.insert(id);
        k = e;
      }
    }
    return out;
  }();
  return ids;
}

// What is missing of a code symbol: "" when the tree has it. `name(...)` must be declared or called as a
// function of its own; `A::b` needs A and b; a CamelCase name must occur.
std::string missingSymbol(const std::string& symbol, bool call) {
  const Identifiers& ids = identifiers();
  std::vector<std::string> parts;
  for (size_t k = 0; k <= symbol.size();) {
    const size_t c = symbol.find("::", k);
    parts.push_back(symbol.substr(k, c == std::string::npos ? std::string::npos : c - k));
    if (c == std::string::npos) break;
    k = c + 2;
  }
  for (size_t k = 0; k < parts.size(); ++k) {
    const bool last = k + 1 == parts.size();
    const auto& set = last && call && parts.size() == 1 ? ids.functions : ids.any;
    if (!set.count(parts[k])) return symbol;
  }
  return "";
}

bool looksLikePath(const std::string& t) {
  static const std::regex ext(R"(\.(h|cpp|md|yaml|launch|py|sh|cmake|rviz|xml|msg|srv|txt)$)");
  return t.find(' ') == std::string::npos && t.find('*') == std::string::npos && t.find('<') == std::string::npos &&
         (std::regex_search(t, ext) || (t.back() == '/' && t.find('/') != t.size() - 1));
}

bool pathExists(const std::string& t) {
  for (const char* base :
       {"", "docs", "include/riser_sim", "include/riser_sim/spatial", "include", "src", "src/core", "src/core/spatial",
        "src/node", "src/cli", "test", "test/core", "test/ros", "bench", "scripts", "config/scenes", "launch", "cmake"})
    if (fs::exists(kRoot / base / t)) return true;
  return false;
}

}  // namespace

TEST(DocsLinks, ArchitectureNamesExist) {
  const std::string text = readFile(kRoot / "docs/architecture.md");
  const std::string md = prose(text);
  const std::regex code("`([^`\n]+)`");
  std::vector<std::string> missing;
  int paths = 0, symbols = 0;
  for (std::sregex_iterator it(md.begin(), md.end(), code), end; it != end; ++it) {
    const std::string t = (*it)[1];
    if (looksLikePath(t)) {
      ++paths;
      if (!pathExists(t)) missing.push_back("file " + t);
      continue;
    }
    // A code symbol: `name(...)`, `Class::member`, `Class` in CamelCase.
    static const std::regex call(R"(^([A-Za-z_][A-Za-z0-9_:]*)\()"),
        qualified(R"(^[A-Za-z_][A-Za-z0-9_]*(::[A-Za-z_][A-Za-z0-9_]*)+$)"),
        camel(R"(^[A-Z][a-z0-9]+[A-Z][A-Za-z0-9]*$)");
    std::smatch m;
    std::string name;
    if (std::regex_search(t, m, call))
      name = m[1];
    else if (std::regex_match(t, qualified) || std::regex_match(t, camel))
      name = t;
    if (name.empty()) continue;
    ++symbols;
    const std::string gone = missingSymbol(name, t.find('(') != std::string::npos);
    if (!gone.empty()) missing.push_back("symbol " + gone);
  }
  // The diagrams in ``` fences: the calls and qualified names they show.
  std::string fences;
  {
    std::istringstream in(text);
    std::string line;
    bool fenced = false;
    while (std::getline(in, line)) {
      if (line.rfind("```", 0) == 0)
        fenced = !fenced;
      else if (fenced)
        fences += line + "\n";
    }
  }
  const std::regex fenced_call(R"(([A-Za-z_][A-Za-z0-9_]*(::[A-Za-z_][A-Za-z0-9_]*)*)\()"),
      fenced_qualified(R"(([A-Z][A-Za-z0-9_]*::[A-Za-z_][A-Za-z0-9_]*))");
  for (const std::regex* re : {&fenced_call, &fenced_qualified})
    for (std::sregex_iterator it(fences.begin(), fences.end(), *re), end; it != end; ++it) {
      ++symbols;
      const std::string gone = missingSymbol((*it)[1], re == &fenced_call);
      if (!gone.empty()) missing.push_back("symbol " + gone + " (in a diagram)");
    }
  EXPECT_GT(paths, 10);
  EXPECT_GT(symbols, 10);
  for (const auto& m : missing) ADD_FAILURE() << "docs/architecture.md names " << m << ", which the tree does not have";
}

TEST(DocsLinks, RelativeLinksAndAnchorsResolve) {
  std::vector<fs::path> pages = {kRoot / "README.md", kRoot / "CHANGELOG.md"};
  for (const auto& e : fs::directory_iterator(kRoot / "docs"))
    if (e.path().extension() == ".md") pages.push_back(e.path());
  const std::regex link(R"(\]\(([^)\s]+)\))");
  int checked = 0;
  for (const fs::path& page : pages) {
    const std::string md = prose(readFile(page));
    for (std::sregex_iterator it(md.begin(), md.end(), link), end; it != end; ++it) {
      const std::string target = (*it)[1];
      if (target.find("://") != std::string::npos || target.rfind("mailto:", 0) == 0) continue;
      const size_t hash = target.find('#');
      const std::string file = target.substr(0, hash);
      const fs::path p = file.empty() ? page : page.parent_path() / file;
      ++checked;
      if (!fs::exists(p)) {
        ADD_FAILURE() << page.filename() << ": link to " << target << ": no such file";
        continue;
      }
      if (hash != std::string::npos && p.extension() == ".md" && !anchors(p).count(target.substr(hash + 1)))
        ADD_FAILURE() << page.filename() << ": link to " << target << ": no such heading";
    }
  }
  EXPECT_GT(checked, 50);
}
