// Cloud model files and `nephele model`: every bad value is refused with exit code 2 naming the
// key, and a run writes its output set (raw volume, sidecar, EXR atlas, the model).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <vector>
#include <sstream>

#include "io/cloud_model_files.hpp"
#include "cli_support.hpp"
#include "gl_support.hpp"
#include "model/density_volume.hpp"
#include "core/json.hpp"
#include "io/model_files.hpp"
#include "model/cloud_model.hpp"
#include "params/table.hpp"

using namespace nephele;

namespace {

// A valid file with one primitive; `top`, `noise` and `primitive` ("\"key\": value, ") add a
// member or replace the default member of that key.
std::string with_member(std::vector<std::pair<std::string, std::string>> members, const std::string& item) {
  if (!item.empty()) {
    const std::string key = item.substr(1, item.find('"', 1) - 1);
    for (auto& m : members)
      if (m.first == key) m = {"", ""};
    members.emplace_back("", item.substr(0, item.size() - 2));
  }
  std::string text;
  for (const auto& [key, value] : members) {
    if (key.empty() && value.empty()) continue;
    text += (text.empty() ? "" : ", ") + (key.empty() ? value : "\"" + key + "\": " + value);
  }
  return "{" + text + "}";
}

std::string cloud_file(const std::string& top = "", const std::string& noise = "", const std::string& primitive = "") {
  const std::string n = with_member({{"octaves", "2"}}, noise);
  const std::string p =
      with_member({{"type", "\"point\""}, {"position", "[0.5, 0.5, 0.5]"}, {"radius", "0.1"}}, primitive);
  return "{" + top + "\"blend\": \"lipus\", \"noise\": " + n + ", \"primitives\": [" + p + "]}";
}

std::string refused(const std::string& text) {
  try {
    io::parse_cloud_model(text, "c.cloud.json");
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "accepted";
}

}  // namespace

TEST_CASE("the test's base cloud file is accepted", "[fast][model]") {
  CHECK_NOTHROW(io::parse_cloud_model(cloud_file(), "c.cloud.json"));
}

TEST_CASE("cloud model files refuse every numeric key just outside the range the table declares, naming the key",
          "[fast][model][params]") {
  namespace cm = params::cloud_model;
  for (const params::Parameter* p : params::all()) {
    if (!p->used_by(params::model_file) || (p->type != params::Type::integer && p->type != params::Type::real))
      continue;
    const std::string key(p->key);
    for (const double value : {p->min - 1.0, p->max + 1.0}) {
      std::ostringstream v;
      v.precision(10);  // as the message shows it (params::check_number)
      v << value;
      std::string text;
      if (p == &cm::scale || p == &cm::extent || p == &cm::base || p == &cm::top)
        text = cloud_file("\"" + key + "\": " + v.str() + ", ");
      else if (p == &cm::coordinate)
        text = cloud_file("", "", "\"position\": [0.5, " + v.str() + ", 0.5], ");
      else if (p == &cm::radius || p == &cm::influence || p == &cm::weight)
        text = cloud_file("", "", "\"" + key + "\": " + v.str() + ", ");
      else
        text = cloud_file("", "\"" + key + "\": " + v.str() + ", ");
      INFO(text);
      CHECK_THAT(refused(text), Catch::Contains(key) && Catch::Contains(v.str()));
    }
  }
}

TEST_CASE("cloud model files refuse unknown and duplicate keys, wrong types, missing skeletons and unequal weights",
          "[fast][model]") {
  const std::map<std::string, std::string> cases = {
      {cloud_file("\"colour\": 1, "), "colour"},
      {cloud_file("\"scale\": 0.1, \"scale\": 0.2, "), "scale"},
      {cloud_file("\"blend\": \"max\", "), "blend"},
      {cloud_file("\"scale\": \"big\", "), "scale"},
      {cloud_file("", "\"seed\": 1.5, "), "noise.seed"},
      {cloud_file("", "\"colour\": 1, "), "noise.colour"},
      {cloud_file("", "", "\"to\": [0, 0, 0], "), "primitives[0].to"},
      {cloud_file("", "", "\"position\": [0.5, 0.5], "), "position"},
      {R"({"primitives": [{"type": "segment", "from": [0.1, 0.1, 0.1], "radius": 0.1}]})", "primitives[0].to"},
      {R"({"primitives": [{"type": "cone", "position": [0.1, 0.1, 0.1]}]})", "primitives[0].type"},
      {R"({"primitives": [{"position": [0.1, 0.1, 0.1]}]})", "primitives[0].type"},
      {R"({"primitives": []})", "primitives"},
      {R"({"blend": "lipus"})", "primitives"},
      {R"({"primitives": [{"type": "point", "position": [0.4, 0.5, 0.5], "weight": 1},
                          {"type": "point", "position": [0.6, 0.5, 0.5], "weight": 0.5}]})",
       "primitives[1].weight"},
      {"[1, 2]", "top level"},
      {"{\"scale\": 0.02", "not valid JSON"},
  };
  for (const auto& [text, key] : cases) {
    INFO(text);
    CHECK_THAT(refused(text), Catch::Contains(key) && Catch::Contains("c.cloud.json"));
  }
}

TEST_CASE("a polyline in a model file is its consecutive segments, with its radius, influence and noise",
          "[fast][model]") {
  const std::string common = R"("radius": 0.05, "influence": 0.08, "noise": {"seed": 9}})";
  const model::CloudModel polyline = io::parse_cloud_model(
      R"({"primitives": [{"type": "polyline", "points": [[0.2, 0.5, 0.8], [0.5, 0.5, 0.82], [0.8, 0.6, 0.8]], )" +
          common + "]}",
      "p.cloud.json");
  const model::CloudModel segments = io::parse_cloud_model(
      R"({"primitives": [{"type": "segment", "from": [0.2, 0.5, 0.8], "to": [0.5, 0.5, 0.82], )" + common +
          R"(, {"type": "segment", "from": [0.5, 0.5, 0.82], "to": [0.8, 0.6, 0.8], )" + common + "]}",
      "s.cloud.json");
  CHECK(polyline.primitives.size() == 2);
  CHECK(io::write_cloud_model(polyline) == io::write_cloud_model(segments));
  CHECK_THAT(refused(R"({"primitives": [{"type": "polyline", "points": [[0.2, 0.5, 0.8]]}]})"),
             Catch::Contains("primitives[0].points") && Catch::Contains("2 to 64"));
  CHECK_THAT(refused(R"({"primitives": [{"type": "polyline", "position": [0.2, 0.5, 0.8]}]})"),
             Catch::Contains("primitives[0].position") && Catch::Contains("points"));
}

TEST_CASE("nephele model refuses bad options and files with exit code 2", "[model][cli]") {
  test::TemporaryDirectory dir(true);
  const auto bad = dir.path / "bad.cloud.json";
  {
    std::ofstream f(bad);
    f << cloud_file("", "", "\"influence\": 0, ");
  }
  for (const std::string& arguments :
       {std::string("model --size 24"), std::string("model --example towering --scene ") + bad.string(),
        std::string("model --example cirrus"), std::string("model --example towering --size 7"),
        std::string("model --example towering --blend max"), std::string("model --scene ") + bad.string(),
        std::string("model --scene ") + (dir.path / "missing.json").string()}) {
    const auto r = test::run(arguments + " --out " + (dir.path / "out").string());
    INFO(arguments << "\n" << r.output);
    CHECK(r.exit_code == 2);
  }
  CHECK_FALSE(std::filesystem::exists(dir.path / "out"));
}

TEST_CASE("nephele model writes the raw volume, its sidecar, the EXR atlas and the model as one set",
          "[model][cli][gpu]") {
  test::TemporaryDirectory out;
  const auto r = test::run("model --example towering --size 20 --preview 32x24 --quiet --out " + out.path.string());
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(std::filesystem::file_size(out.path / "density.raw") == 20u * 20u * 20u * 4u);
  CHECK(std::filesystem::exists(out.path / "density_atlas.exr"));
  CHECK(std::filesystem::exists(out.path / "preview.png"));
  CHECK(std::filesystem::exists(out.path / "density.vdb") == io::vdb_available());
  const json::Value sidecar = json::parse(test::read_file(out.path / "density.json"));
  CHECK(sidecar.at("size").as_number() == 20);
  CHECK(sidecar.at("voxel_size_m").as_number() == 6000.0 / 20);
  CHECK(sidecar.at("density_to_extinction_per_m").as_number() == io::density_to_extinction_per_m);
  CHECK(sidecar.at("range").at("max").as_number() > 0.5);
  // The model written beside the volume reads back as the example.
  CHECK(io::write_cloud_model(io::read_cloud_model((out.path / "model.cloud.json").string())) ==
        io::write_cloud_model(model::example("towering")));
}

TEST_CASE("density.vdb reads back through OpenVDB with its voxels, grid class, voxel size and orientation",
          "[model][vdb][gpu]") {
  if (!io::vdb_available()) {
    WARN("built without OpenVDB: no .vdb to read back");
    return;
  }
  test::test_context();
  // One point off every axis's centre, without noise: the density's centroid lies at the
  // point, so a swapped or mirrored axis moves it by at least 0.1 x extent = 20 voxels.
  model::CloudModel m;
  m.blend = model::Blend::lipus;
  m.extent_m = 1000;
  model::Primitive p;
  p.from = p.to = glsl::vec3(0.25f, 0.6f, 0.75f);
  p.radius = 0.05f;
  p.influence = 0.1f;
  m.primitives = {p};
  const int size = 32;
  model::DensityVolume volume(size);
  volume.compute(m);
  const auto values = volume.read();
  test::TemporaryDirectory dir(true);
  const auto path = dir.path / "density.vdb";
  {
    const std::string bytes = io::vdb_bytes(m, size, values);
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
  }
  const io::VdbContents c = io::read_vdb(path.string());
  CHECK(c.grids == std::vector<std::string>{"density"});
  CHECK(c.fog_volume);
  CHECK(c.background == 0.0f);
  const double s = 1000.0 / size;
  CHECK(c.voxel_size == Approx(s).epsilon(1e-12));
  for (double o : c.origin) CHECK(o == Approx(s / 2).epsilon(1e-12));  // voxel (0, 0, 0) centred at s/2
  CHECK(c.extinction_per_m == io::density_to_extinction_per_m);
  // Sparse: exactly the voxels above 0 are active, with the raw volume's values.
  const long nonzero = long(std::count_if(values.begin(), values.end(), [](float v) { return v > 0.0f; }));
  CHECK(c.active == nonzero);
  CHECK(nonzero < long(values.size()) / 4);
  double weight = 0, centroid[3] = {0, 0, 0};
  for (const auto& v : c.values) {
    REQUIRE(v.value == values[(size_t(v.z) * size + v.y) * size + v.x]);
    const int k[3] = {v.x, v.y, v.z};
    for (int a = 0; a < 3; ++a) centroid[a] += v.value * (k[a] + 0.5) * s;
    weight += v.value;
  }
  // The field is symmetric about the point; voxel centres sample it symmetrically up to one
  // voxel's shift: within one voxel s of the point in world metres.
  for (int a = 0; a < 3; ++a) CHECK(std::abs(centroid[a] / weight - 1000.0 * p.from[a]) <= s);
}
