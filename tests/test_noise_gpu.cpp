// Tileable noise textures on the GPU against their CPU twin, and nephele noise end to end.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "apps/cli/noise_options.hpp"
#include "apps/cli/options.hpp"
#include "files/image_files.hpp"
#include "cli_support.hpp"
#include "gl_support.hpp"
#include "io/noise_files.hpp"
#include "noise/noise_texture.hpp"
#include "shader_math/shader_math.hpp"
#include "core/json.hpp"
#include "tolerances.hpp"

namespace fs = std::filesystem;
using namespace nephele;
using test::read_file;
using test::Run;
using test::run;
using test::TemporaryDirectory;
using namespace nephele::glsl;
using nephele::test::probe;

namespace {

noise::TextureSpec spec_of(int w, int h, int d, noise::NoiseType type, int cells, int octaves) {
  noise::TextureSpec spec;
  spec.width = w;
  spec.height = h;
  spec.depth = d;
  spec.seed = 3;
  spec.channels[0].type = type;
  spec.channels[0].cells = cells;
  spec.channels[0].octaves = octaves;
  spec.channels[0].worley_cells = cells;
  spec.channels[0].worley_octaves = 2;
  return spec;
}

using nephele::test::kUlp;

// Perlin noise at points up to 30 (no frequency: the fraction p - floor(p) is exact on both
// sides): the same float operations except that the GPU may contract a * b + c, which changes
// a result by at most one rounding; perlin.glsl chains at most 16 such operations (fade 5,
// weights 2, dot products and sums 5, the mixes 4; kPerlin of test_library_probes.cpp) on
// values below 2 (2^-23 each): 1.9e-6; 2e-6. Tighter than test_library_probes' kPerlin, which
// also allows GLSL's division error (perlin_noise divides nothing).
constexpr double kPerlinGpu = 2.0e-6;
static_assert(kPerlinGpu >= 16 * 2 * kUlp);

// GPU and CPU run the same float operations except that the GPU may fuse a * b + c: a few
// rounding steps of 2^-24 on values below 4 through at most ~30 operations per octave
// (30 x 4 x 2^-24 = 7.2e-6), and the final divisions by sums of amplitudes >= 1 do not amplify
// them: 1e-5.
constexpr float kTextureGpu = 1e-5f;
static_assert(kTextureGpu >= 30 * 4 * kUlp);
// An 8-bit PNG holds round(255 v) / 255: half a quantisation step from the (GPU) value, which is
// within kTextureGpu of the CPU twin's.
constexpr double kPng8 = 0.5 / 255 + 1e-5;
static_assert(kPng8 >= 0.5 / 255 + kTextureGpu);
// A 16-bit PNG against the float EXR of the same texture: half a step of 1/65535, plus the
// float roundings of v 65535 when writing and q / 65535 when reading (2 x 2^-24 of values
// below 1, 1.2e-7); 1e-6 leaves a factor 8.
constexpr double kPng16 = 0.5 / 65535 + 1e-6;
static_assert(kPng16 >= 0.5 / 65535 + 2 * kUlp);
// The sidecar's range minimum, from the GPU values, against the CPU twin's minimum: kTextureGpu.
constexpr double kRangeMinimum = 1e-5;
static_assert(kRangeMinimum >= kTextureGpu);

}  // namespace

TEST_CASE("perlin noise on the GPU agrees with the CPU", "[probe][noise]") {
  const uvec3 key = noise_key(5u, 2u);
  std::mt19937 rng(6);
  std::uniform_real_distribution<float> u(-30.0f, 30.0f);
  std::vector<vec4> inputs(512);
  for (auto& p : inputs) p = vec4(u(rng), u(rng), u(rng), 0.0f);
  const std::string key_text =
      "uvec3(" + std::to_string(key.x) + "u, " + std::to_string(key.y) + "u, " + std::to_string(key.z) + "u)";
  const auto gpu = probe<vec4>("#include \"../lib/perlin.glsl\"",
                               "perlin_noise(input_value.xyz, ivec3(7, 3, 5), " + key_text +
                                   "), perlin_noise(input_value.xyz, ivec3(0), " + key_text + "), 0.0, 0.0",
                               inputs);
  for (size_t k = 0; k < inputs.size(); ++k) {
    // Same operations up to fused multiply-adds: a few ulp of terms below 2.
    REQUIRE(gpu[k].x == Approx(perlin_noise(vec3(inputs[k]), ivec3(7, 3, 5), key)).epsilon(0).margin(kPerlinGpu));
    REQUIRE(gpu[k].y == Approx(perlin_noise(vec3(inputs[k]), ivec3(0), key)).epsilon(0).margin(kPerlinGpu));
  }
}

TEST_CASE("the GPU texture generator agrees with its CPU twin for every channel type", "[gpu][noise]") {
  test::test_context();
  using noise::NoiseType;
  noise::TextureGenerator generator;
  const noise::TextureSpec specs[] = {
      spec_of(16, 16, 16, NoiseType::worley, 4, 1),
      spec_of(72, 8, 8, NoiseType::inverted_worley, 9, 3),  // two row segments
      spec_of(16, 16, 8, NoiseType::perlin, 2, 4),
      spec_of(20, 10, 5, NoiseType::perlin, 4, 1),
      spec_of(100, 20, 20, NoiseType::perlin, 5, 1),  // cells of 20 texels: perlin_row_wide, a partial segment
      spec_of(128, 16, 16, NoiseType::perlin, 8,
              2),  // the finishing octave walked wide           // rows not a multiple of 8
      spec_of(16, 8, 8, NoiseType::perlin_worley, 2, 3),
      spec_of(12, 12, 12, NoiseType::worley, 6, 2),  // cells of one texel at octave 2
  };
  long patched = 0;
  for (const auto& spec : specs) {
    const noise::Volume gpu = generator.generate(spec);
    patched += generator.timings().patched_segments;
    const noise::Volume cpu = noise::generate_cpu(spec);
    REQUIRE(gpu.values.size() == cpu.values.size());
    for (size_t k = 0; k < cpu.values.size(); ++k) {
      INFO(noise::type_name(spec.channels[0].type) << " value " << k);
      REQUIRE(gpu.values[k] == Approx(cpu.values[k]).epsilon(0).margin(kTextureGpu));
    }
  }
  // Some segments had texels with F1 > 1, so the patch pass ran and agreed as well.
  CHECK(patched > 0);
}

TEST_CASE("textures split into slabs equal textures made in one dispatch", "[gpu][noise]") {
  test::test_context();
  noise::TextureSpec spec = spec_of(16, 16, 12, noise::NoiseType::perlin_worley, 4, 2);
  spec.channels.push_back(spec_of(16, 16, 12, noise::NoiseType::worley, 8, 1).channels[0]);
  noise::TextureGenerator whole;
  // Five slices per dispatch: rows are padded to a whole segment of floats.
  noise::TextureGenerator slices(static_cast<size_t>(NOISE_SEGMENT) * 16 * sizeof(float) * 5);
  const noise::Volume a = whole.generate(spec);
  const noise::Volume b = slices.generate(spec);
  CHECK(whole.timings().dispatches == 2);
  CHECK(slices.timings().dispatches == 2 * 3);
  CHECK(a.values == b.values);
}

TEST_CASE("the slice atlas puts slice z at columns z times width", "[fast][noise]") {
  noise::Volume v{3, 2, 4, 2, {}};
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 3; ++x)
        for (int c = 0; c < 2; ++c) v.values.push_back(float(1000 * c + 100 * z + 10 * y + x));
  const std::vector<float> atlas = io::slice_atlas(v);
  const int atlas_width = 3 * 4;
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 3; ++x)
        for (int c = 0; c < 2; ++c) REQUIRE(atlas[(y * atlas_width + z * 3 + x) * 2 + c] == v.at(x, y, z, c));
}

TEST_CASE("noise options refuse bad values naming the option and its range", "[fast][cli][noise]") {
  auto message = [](const std::vector<std::string>& arguments) {
    try {
      cli::parse_noise_request(arguments);
    } catch (const cli::UsageError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string out = (fs::temp_directory_path() / "n.png").string();
  CHECK_THAT(message({"--width", "0", "--out", out}), Catch::Contains("--width") && Catch::Contains("1 to"));
  CHECK_THAT(message({"--size", "-4", "--out", out}), Catch::Contains("--size"));
  CHECK_THAT(message({"--width", "32", "--height", "20", "--cells", "10", "--out", out}),
             Catch::Contains("--cells") && Catch::Contains("multiple of 8"));
  CHECK_THAT(message({"--type", "simplex", "--out", out}),
             Catch::Contains("--type") && Catch::Contains("perlin-worley"));
  CHECK_THAT(message({"--channels", "rgbx", "--out", out}), Catch::Contains("--channels"));
  CHECK_THAT(message({"--size", "16", "--channels", "rgba", "--a", "cells=32", "--out", out}),
             Catch::Contains("cells") && Catch::Contains("channel a") && Catch::Contains("1 to 16"));
  CHECK_THAT(message({"--g", "octaves=3", "--out", out}), Catch::Contains("--g"));
  CHECK_THAT(message({"--channels", "rg", "--g", "type=perlin,cells=fast", "--out", out}),
             Catch::Contains("--g cells"));
  CHECK_THAT(message({"--preset", "shape", "--size", "64", "--out", out}), Catch::Contains("--preset"));
  CHECK_THAT(message({"--size", "16", "--out", (fs::temp_directory_path() / "n.tiff").string()}),
             Catch::Contains("--out"));
  CHECK_THAT(message({"--size", "16"}), Catch::Contains("--out"));
  CHECK_THAT(message({"--bits", "12", "--out", out}), Catch::Contains("--bits"));
  CHECK(message({"--width", "32", "--height", "32", "--depth", "32", "--cells", "10", "--out", out}).empty());
  const cli::NoiseRequest rgba =
      cli::parse_noise_request({"--type", "perlin-worley", "--size", "128", "--channels", "rgba", "--seed", "3", "--b",
                                "type=worley,octaves=2", "--out", out});
  REQUIRE(rgba.spec.channels.size() == 4);
  CHECK(rgba.spec.channels[3].cells == 32);
  CHECK(rgba.spec.channels[2].type == noise::NoiseType::worley);
  CHECK(rgba.spec.channels[2].octaves == 2);
  CHECK(rgba.spec.seed == 3);
  // The default doubling per channel stops at one cell per texel: 4, 8, 16, 16 on 16 texels.
  const cli::NoiseRequest small = cli::parse_noise_request({"--size", "16", "--channels", "rgba", "--out", out});
  REQUIRE(small.spec.channels.size() == 4);
  CHECK(small.spec.channels[1].cells == 8);
  CHECK(small.spec.channels[2].cells == 16);
  CHECK(small.spec.channels[3].cells == 16);
}

TEST_CASE("sizes beyond the driver's 3D texture limit give exit code 2 and write nothing", "[cli][noise]") {
  test::test_context();
  GLint limit = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &limit);
  TemporaryDirectory out(true);
  // Twice the limit along x with whole cells on every axis (one along y and z).
  const Run r = run("noise --width " + std::to_string(2 * limit) + " --height 8 --depth 8 --cells " +
                    std::to_string(2 * limit / 8) + " --out " + (out.path / "big.raw").string());
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.output, Catch::Contains("--width") && Catch::Contains("3D texture limit"));
  CHECK(out.empty());
  // More than the memory available (and not more than the texture limit).
  const Run memory =
      run("noise --size " + std::to_string(limit) + " --channels rgba --out " + (out.path / "huge.raw").string());
  INFO(memory.output);
  CHECK(memory.exit_code == 2);
  CHECK_THAT(memory.output, Catch::Contains("MiB") && Catch::Contains("available"));
  CHECK(out.empty());
  const Run bad = run("noise --size 16 --cells 3 --octaves 4 --out " + (out.path / "x.png").string());
  CHECK(bad.exit_code == 2);
  CHECK_THAT(bad.output, Catch::Contains("--octaves"));
  CHECK(out.empty());
}

TEST_CASE("nephele noise writes the slice atlas and a sidecar that describes it", "[cli][noise]") {
  TemporaryDirectory out(true);
  const fs::path png = out.path / "worley.png";
  const Run r = run("noise --width 16 --height 8 --depth 4 --cells 4 --seed 9 --out " + png.string());
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto image = files::read_image(png);
  CHECK(image.width == 16 * 4);
  CHECK(image.height == 8);
  CHECK(image.channels == 1);
  const json::Value sidecar = json::parse(read_file(out.path / "worley.json"));
  CHECK(sidecar.at("width").as_number() == 16);
  CHECK(sidecar.at("depth").as_number() == 4);
  CHECK(sidecar.at("seed").as_number() == 9);
  CHECK(sidecar.at("format").as_string() == "png8");
  const json::Value& channel = sidecar.at("channel_parameters").as_array().at(0);
  CHECK(channel.at("type").as_string() == "worley");
  CHECK(channel.at("fbm").at("cells").as_array().at(1).as_number() == 2);  // cells follow the aspect
  // The PNG holds the CPU twin's values quantised to 8 bits.
  noise::TextureSpec spec = spec_of(16, 8, 4, noise::NoiseType::worley, 4, 1);
  spec.seed = 9;
  const noise::Volume cpu = noise::generate_cpu(spec);
  const float lo = static_cast<float>(channel.at("range").at("min").as_number());
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 16; ++x)
        REQUIRE(image.pixels[y * 64 + z * 16 + x] == Approx(cpu.at(x, y, z, 0)).epsilon(0).margin(kPng8));
  CHECK(lo == Approx(*std::min_element(cpu.values.begin(), cpu.values.end())).epsilon(0).margin(kRangeMinimum));
}

TEST_CASE("nephele noise writes float EXR atlases 16 bit PNGs and raw volumes", "[cli][noise]") {
  TemporaryDirectory out(true);
  const std::string common = " --size 16 --cells 2 --worley-octaves 2 --type perlin-worley --channels rgb --seed 4";
  const Run exr = run("noise" + common + " --out " + (out.path / "t.exr").string());
  INFO(exr.output);
  REQUIRE(exr.exit_code == 0);
  const auto image = files::read_image(out.path / "t.exr");
  CHECK(image.width == 16 * 16);
  CHECK(image.channels == 3);
  const Run raw = run("noise" + common + " --out " + (out.path / "t.raw").string());
  REQUIRE(raw.exit_code == 0);
  const std::string bytes = read_file(out.path / "t.raw");
  REQUIRE(bytes.size() == 16 * 16 * 16 * 3 * sizeof(float));
  std::vector<float> values(bytes.size() / sizeof(float));
  std::memcpy(values.data(), bytes.data(), bytes.size());
  // The same texture in both: raw (x, y, z, c) at ((z * 16 + y) * 16 + x) * 3 + c, atlas at column z * 16 + x.
  for (int z = 0; z < 16; ++z)
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x)
        for (int c = 0; c < 3; ++c)
          REQUIRE(values[((z * 16 + y) * 16 + x) * 3 + c] == image.pixels[(y * 256 + z * 16 + x) * 3 + c]);
  const json::Value sidecar = json::parse(read_file(out.path / "t.json"));
  CHECK(sidecar.at("format").as_string() == "raw-float32-little-endian");
  CHECK(sidecar.at("channels").as_string() == "rgb");
  CHECK(sidecar.at("channel_parameters").as_array().size() == 3);
  const Run png16 = run("noise" + common + " --bits 16 --out " + (out.path / "t16.png").string());
  REQUIRE(png16.exit_code == 0);
  const auto deep = files::read_image(out.path / "t16.png");
  for (size_t k = 0; k < deep.pixels.size(); ++k)
    REQUIRE(deep.pixels[k] == Approx(image.pixels[k]).epsilon(0).margin(kPng16));
}

TEST_CASE("stretch maps each channel's range onto 0 to 1 and records the range before", "[cli][noise]") {
  TemporaryDirectory out(true);
  const Run r =
      run("noise --size 16 --cells 2 --channels rg --type perlin --stretch --out " + (out.path / "s.exr").string());
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto image = files::read_image(out.path / "s.exr");
  const json::Value sidecar = json::parse(read_file(out.path / "s.json"));
  for (int c = 0; c < 2; ++c) {
    float lo = 1.0f, hi = 0.0f;
    for (size_t k = c; k < image.pixels.size(); k += 2) {
      lo = std::min(lo, image.pixels[k]);
      hi = std::max(hi, image.pixels[k]);
    }
    CHECK(lo == 0.0f);
    CHECK(hi == 1.0f);
    const json::Value& before = sidecar.at("channel_parameters").as_array().at(c).at("stretched_from");
    CHECK(before.at("min").as_number() > 0.0);
    CHECK(before.at("max").as_number() < 1.0);
  }
}
