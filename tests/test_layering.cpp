// The layers of src/ (docs/architecture.md): every CMake link, C++ #include and GLSL #include
// goes down the order that src/CMakeLists.txt declares, never up or sideways into a layer that
// was not linked.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

struct LayerGraph {
  std::vector<std::string> order;                         // lowest first
  std::map<std::string, std::vector<std::string>> links;  // layer -> layers it links
};

LayerGraph parse_layer_graph(const std::string& text) {
  LayerGraph graph;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string kind, word;
    words >> kind;
    if (kind == "order") {
      while (words >> word) graph.order.push_back(word);
    } else if (kind == "links") {
      std::string name;
      words >> name;
      auto& list = graph.links[name];
      while (words >> word) list.push_back(word);
    }
  }
  return graph;
}

int rank_of(const LayerGraph& graph, const std::string& layer) {
  const auto it = std::find(graph.order.begin(), graph.order.end(), layer);
  return it == graph.order.end() ? -1 : static_cast<int>(it - graph.order.begin());
}

// Links that do not go strictly down the order, as "from -> to" lines.
std::vector<std::string> upward_links(const LayerGraph& graph) {
  std::vector<std::string> bad;
  for (const auto& [from, targets] : graph.links)
    for (const auto& to : targets)
      if (rank_of(graph, from) < 0 || rank_of(graph, to) < 0 || rank_of(graph, to) >= rank_of(graph, from))
        bad.push_back(from + " -> " + to);
  return bad;
}

// The layers a layer may include from: itself and everything it reaches through links.
std::set<std::string> reachable(const LayerGraph& graph, const std::string& layer) {
  std::set<std::string> seen{layer};
  std::vector<std::string> stack{layer};
  while (!stack.empty()) {
    const std::string top = stack.back();
    stack.pop_back();
    const auto it = graph.links.find(top);
    if (it == graph.links.end()) continue;
    for (const auto& next : it->second)
      if (seen.insert(next).second) stack.push_back(next);
  }
  return seen;
}

// The layer of a path under src/ (or of an include path): its first folder, or its first two for
// the apps (apps/cli, apps/viewer).
std::string layer_of_path(const std::string& path) {
  const auto slash = path.find('/');
  const std::string head = path.substr(0, slash);
  if (head != "apps" || slash == std::string::npos) return head;
  return path.substr(0, path.find('/', slash + 1));
}

// The layer an include path belongs to, with the generated version header in core and the GLSL
// library (compiled as C++) in shader_math.
std::string layer_of_include(const std::string& path) {
  const std::string head = layer_of_path(path);
  if (head == "nephele") return "core";
  if (head == "lib") return "shader_math";
  return head;
}

std::vector<std::string> quoted_includes(const fs::path& file) {
  static const std::regex include_line(R"re(^\s*#\s*include\s+"([^"]+)")re");
  std::vector<std::string> out;
  std::ifstream in(file);
  std::string line;
  std::smatch match;
  while (std::getline(in, line))
    if (std::regex_search(line, match, include_line)) out.push_back(match[1].str());
  return out;
}

// Includes of the C++ files under `source_root` that reach a layer the file's layer was not
// linked to, as "file: include" lines. A file's layer is layer_of_path of its path under src/.
std::vector<std::string> upward_includes(const LayerGraph& graph, const fs::path& source_root) {
  std::vector<std::string> bad;
  for (const auto& entry : fs::recursive_directory_iterator(source_root)) {
    const std::string extension = entry.path().extension().string();
    if (!entry.is_regular_file() || (extension != ".cpp" && extension != ".hpp")) continue;
    const fs::path relative = fs::relative(entry.path(), source_root);
    const std::string layer = layer_of_path(relative.generic_string());
    const std::set<std::string> allowed = reachable(graph, layer);
    for (const auto& include : quoted_includes(entry.path())) {
      const std::string target = layer_of_include(include);
      if (!allowed.count(target)) bad.push_back(relative.string() + ": " + include);
    }
  }
  return bad;
}

// GLSL: the library (shaders/lib) includes only itself; a stage's shaders include the library
// and their own folder.
std::vector<std::string> stray_shader_includes(const fs::path& shader_root) {
  std::vector<std::string> bad;
  for (const auto& entry : fs::recursive_directory_iterator(shader_root)) {
    if (!entry.is_regular_file()) continue;
    const fs::path relative = fs::relative(entry.path(), shader_root);
    const std::string folder = relative.begin()->string();
    for (const auto& include : quoted_includes(entry.path())) {
      // Includes resolve against the including file's folder.
      const fs::path resolved = (relative.parent_path() / include).lexically_normal();
      const std::string target = resolved.begin()->string();
      if (target != "lib" && target != folder) bad.push_back(relative.string() + ": " + include);
    }
  }
  return bad;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string join(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

}  // namespace

TEST_CASE("the layer checks find a link, a C++ include and a GLSL include that go upward", "[fast]") {
  const LayerGraph graph = parse_layer_graph("order core gpu cover render\nlinks gpu core\nlinks cover gpu render\n");
  CHECK(upward_links(graph) == std::vector<std::string>{"cover -> render"});

  const fs::path root = fs::temp_directory_path() / ("nephele_layering_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "src/gpu");
  fs::create_directories(root / "src/cover");
  fs::create_directories(root / "shaders/lib");
  fs::create_directories(root / "shaders/cover");
  std::ofstream(root / "src/gpu/context.cpp") << "#include \"gpu/context.hpp\"\n#include \"cover/pass.hpp\"\n";
  std::ofstream(root / "src/cover/pass.cpp") << "#include \"gpu/context.hpp\"\n#include \"core/json.hpp\"\n";
  std::ofstream(root / "shaders/lib/a.glsl") << "#include \"d.glsl\"\n#include \"../cover/b.glsl\"\n";
  std::ofstream(root / "shaders/cover/b.comp") << "#include \"../lib/a.glsl\"\n#include \"../render/c.glsl\"\n";
  const LayerGraph fine = parse_layer_graph("order core gpu cover\nlinks gpu core\nlinks cover gpu\n");
  CHECK(upward_includes(fine, root / "src") == std::vector<std::string>{"gpu/context.cpp: cover/pass.hpp"});
  const auto shader_problems = stray_shader_includes(root / "shaders");
  CHECK(shader_problems.size() == 2);
  fs::remove_all(root);
}

TEST_CASE("every layer links only layers below it", "[fast]") {
  const LayerGraph graph = parse_layer_graph(read_text(NEPHELE_LAYER_LINKS_FILE));
  REQUIRE(graph.order.size() >= 10);
  REQUIRE(graph.links.size() == graph.order.size());
  INFO(join(upward_links(graph)));
  CHECK(upward_links(graph).empty());
}

TEST_CASE("every C++ include of src/ stays within the layers its folder links", "[fast]") {
  const LayerGraph graph = parse_layer_graph(read_text(NEPHELE_LAYER_LINKS_FILE));
  const auto bad = upward_includes(graph, fs::path(NEPHELE_SOURCE_DIR) / "src");
  INFO(join(bad));
  CHECK(bad.empty());
  // Every folder of src/ (of src/apps: every app's folder) is a declared layer.
  const fs::path src = fs::path(NEPHELE_SOURCE_DIR) / "src";
  for (const auto& entry : fs::directory_iterator(src))
    if (entry.is_directory() && entry.path().filename() != "apps")
      CHECK(rank_of(graph, entry.path().filename().string()) >= 0);
  for (const auto& entry : fs::directory_iterator(src / "apps"))
    if (entry.is_directory()) CHECK(rank_of(graph, "apps/" + entry.path().filename().string()) >= 0);
}

TEST_CASE("GLSL includes stay within the library and the shader's own folder", "[fast]") {
  const auto bad = stray_shader_includes(fs::path(NEPHELE_SOURCE_DIR) / "shaders");
  INFO(join(bad));
  CHECK(bad.empty());
}
