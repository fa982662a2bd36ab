#include "gpu/shader_sources.hpp"

#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

namespace nephele::gpu {
namespace {

std::string directory_of(const std::string& path) {
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? "" : path.substr(0, slash + 1);
}

// Resolves "a/b/../c" style paths so that includes relative to a file find their target.
std::string normalise_path(const std::string& path) {
  std::vector<std::string> parts;
  std::stringstream stream(path);
  std::string part;
  while (std::getline(stream, part, '/')) {
    if (part.empty() || part == ".") continue;
    if (part == ".." && !parts.empty()) {
      parts.pop_back();
      continue;
    }
    parts.push_back(part);
  }
  std::string result;
  for (size_t i = 0; i < parts.size(); ++i) result += (i ? "/" : "") + parts[i];
  return result;
}

struct Expander {
  const std::map<std::string, std::string>& sources;
  const std::pair<std::string, std::string>* extra = nullptr;  // (path, text) not embedded
  ExpandedShader out;
  std::set<std::string> included;
  std::vector<std::string> stack;

  int file_index(const std::string& path) {
    for (size_t i = 0; i < out.files.size(); ++i)
      if (out.files[i] == path) return static_cast<int>(i);
    out.files.push_back(path);
    return static_cast<int>(out.files.size() - 1);
  }

  void expand(const std::string& path, const std::string& included_from,
              const std::vector<std::pair<std::string, std::string>>* defines) {
    for (const auto& s : stack)
      if (s == path) throw std::runtime_error("shader include cycle through " + path);
    if (!included.insert(path).second) return;
    const std::string* text = nullptr;
    if (extra && extra->first == path) {
      text = &extra->second;
    } else if (const auto found = sources.find(path); found != sources.end()) {
      text = &found->second;
    } else {
      throw std::runtime_error("shader file '" + path + "' not found" +
                               (included_from.empty() ? "" : " (included from " + included_from + ")"));
    }
    stack.push_back(path);
    const int index = file_index(path);
    std::istringstream lines(*text);
    std::string line;
    int number = 0;
    static const std::regex include_pattern(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
    static const std::regex version_pattern(R"(^\s*#\s*version\b.*)");
    bool line_marked = false;
    while (std::getline(lines, line)) {
      ++number;
      std::smatch match;
      if (std::regex_match(line, match, include_pattern)) {
        expand(normalise_path(directory_of(path) + match[1].str()), path + ":" + std::to_string(number), nullptr);
        out.text += "#line " + std::to_string(number + 1) + " " + std::to_string(index) + "\n";
        continue;
      }
      if (std::regex_match(line, version_pattern)) {
        out.text += line + "\n";
        if (defines)
          for (const auto& [name, value] : *defines) out.text += "#define " + name + " " + value + "\n";
        out.text += "#line " + std::to_string(number + 1) + " " + std::to_string(index) + "\n";
        line_marked = true;
        continue;
      }
      if (!line_marked && number == 1 && stack.size() > 1) {
        out.text += "#line 1 " + std::to_string(index) + "\n";
        line_marked = true;
      }
      out.text += line + "\n";
    }
    stack.pop_back();
  }
};

}  // namespace

ExpandedShader expand_shader(const std::string& path, const std::vector<std::pair<std::string, std::string>>& defines) {
  Expander expander{embedded_shader_sources(), nullptr, {}, {}, {}};
  expander.expand(normalise_path(path), "", &defines);
  return expander.out;
}

ExpandedShader expand_shader_text(const std::string& path, const std::string& text,
                                  const std::vector<std::pair<std::string, std::string>>& defines) {
  const std::pair<std::string, std::string> extra{normalise_path(path), text};
  Expander expander{embedded_shader_sources(), &extra, {}, {}, {}};
  expander.expand(extra.first, "", &defines);
  return expander.out;
}

std::string name_files_in_log(const std::string& log, const std::vector<std::string>& files) {
  static const std::regex mesa(R"(^(\d+):(\d+)\((\d+)\))");
  static const std::regex nvidia(R"(^(\d+)\((\d+)\))");
  std::istringstream lines(log);
  std::string line, result;
  while (std::getline(lines, line)) {
    std::smatch m;
    auto name = [&](const std::string& index) {
      const size_t i = std::stoul(index);
      return i < files.size() ? files[i] : "source " + index;
    };
    if (std::regex_search(line, m, mesa))
      line = name(m[1]) + ":" + m[2].str() + ":" + m[3].str() + line.substr(m[0].length());
    else if (std::regex_search(line, m, nvidia))
      line = name(m[1]) + ":" + m[2].str() + line.substr(m[0].length());
    result += line + "\n";
  }
  return result;
}

}  // namespace nephele::gpu
