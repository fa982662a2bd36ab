// Golden hashes: covers, noise volumes, a model and renders of fixed seeds must stay bit-identical
// on the same renderer while code moves (issue 28's refactors). The outputs are made by the
// command line, the way users make them, and hashed after decoding (no file metadata).
// GPU results depend on the renderer (llvmpipe's vector width, a GPU's driver), so the store,
// tests/data/golden/hashes.json, holds one entry per renderer string; scripts/golden-hashes.sh
// records this machine's. Where the store has no entry for the renderer, the test makes every
// output twice and checks that the two agree bit for bit.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "cli_support.hpp"
#include "core/hash.hpp"
#include "core/json.hpp"
#include "gl_support.hpp"
#include "files/image_files.hpp"

namespace fs = std::filesystem;
using namespace nephele;

namespace {

const fs::path store = fs::path(NEPHELE_SOURCE_DIR) / "tests" / "data" / "golden" / "hashes.json";

std::string hex(std::uint64_t value) {
  std::ostringstream text;
  text << std::hex << value;
  return text.str();
}

std::uint64_t hash_pixels(const fs::path& image, std::uint64_t seed = 0) {
  const core::ImageData data = files::read_image(image);
  return core::block_hash(data.pixels.data(), data.pixels.size() * sizeof(float), seed);
}

std::uint64_t hash_bytes(const fs::path& file) {
  const std::string bytes = test::read_file(file);
  return core::block_hash(bytes.data(), bytes.size());
}

void run_ok(const std::string& arguments) {
  const test::Run r = test::run(arguments);
  INFO(arguments << "\n" << r.output);
  REQUIRE(r.exit_code == 0);
}

// The outputs and their hashes, by name.
std::map<std::string, std::string> make_and_hash() {
  test::TemporaryDirectory out(true);
  const fs::path d = out.path;
  std::map<std::string, std::string> hashes;

  run_ok("generate --size 32 --seed 7 --files faces --quiet --out " + (d / "cover").string());
  std::uint64_t cover = 0;
  for (const char* face : {"px", "nx", "py", "ny", "pz", "nz"})
    cover = hash_pixels(d / "cover" / (std::string("cover_") + face + ".exr"), cover);
  hashes["cover 32 seed 7"] = hex(cover);

  run_ok(
      "noise --size 16 --seed 3 --cells 2 --channels rgba --r type=worley,octaves=3 --g type=perlin,octaves=3 "
      "--b type=perlin-worley,worley-cells=2 --a type=inverted-worley --out " +
      (d / "noise.raw").string());
  hashes["noise 16^3 rgba seed 3"] = hex(hash_bytes(d / "noise.raw"));

  run_ok("model --example towering --size 24 --no-preview --quiet --out " + (d / "model").string());
  hashes["model towering 24^3"] = hex(hash_bytes(d / "model" / "density.raw"));

  run_ok("render --view gurten --size 32x18 --quality draft --quiet --out " + (d / "gurten.exr").string());
  hashes["render gurten 32x18 draft"] = hex(hash_pixels(d / "gurten.exr"));

  run_ok("render --scene " + (fs::path(NEPHELE_SOURCE_DIR) / "scenes" / "gurten-thunderstorm.json").string() +
         " --size 32x18 --quality draft --quiet --out " + (d / "thunderstorm.exr").string());
  hashes["render gurten-thunderstorm 32x18 draft"] = hex(hash_pixels(d / "thunderstorm.exr"));

  run_ok("render --view orbit --size 32x18 --quiet --out " + (d / "orbit.exr").string());
  hashes["render orbit 32x18"] = hex(hash_pixels(d / "orbit.exr"));
  return hashes;
}

}  // namespace

TEST_CASE("covers, noise volumes, a model and renders of fixed seeds are bit-identical to the record of the renderer",
          "[golden][cli]") {
  const std::string renderer = test::test_context().info().renderer;
  json::Value recorded = json::Value::Object{};
  if (fs::exists(store)) recorded = json::parse(test::read_file(store));
  const std::map<std::string, std::string> made = make_and_hash();
  INFO("renderer: " << renderer);
  if (const char* record = std::getenv("NEPHELE_GOLDEN_RECORD"); record && std::string(record) == "1") {
    json::Value entry = json::Value::Object{};
    for (const auto& [name, hash] : made) entry.set(name, hash);
    recorded.set(renderer, entry);
    std::ofstream(store) << json::write(recorded) << "\n";
    WARN("recorded the hashes of " << renderer << " in " << store.string());
    return;
  }
  const json::Value* entry = recorded.find(renderer);
  if (!entry) {
    WARN("no golden hashes for " << renderer
                                 << " (scripts/golden-hashes.sh records them): checking that a second "
                                    "run makes the same outputs");
    CHECK(make_and_hash() == made);
    return;
  }
  for (const auto& [name, hash] : made) {
    INFO(name);
    const json::Value* expected = entry->find(name);
    REQUIRE(expected);
    CHECK(expected->as_string() == hash);
  }
  CHECK(entry->as_object().size() == made.size());
}
