// The implicit cloud modeller (src/model, shaders/lib/implicit_field.glsl): the Wyvill field,
// Lipus's blend, eq. 5 against eq. 6, brick culling and one-primitive edits against brute
// force, the GPU volume against its CPU twin, and the examples' files.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

#include "io/cloud_model_files.hpp"
#include "gl_support.hpp"
#include "model/bricks.hpp"
#include "model/cloud_model.hpp"
#include "model/density_volume.hpp"
#include "render/model_preview.hpp"

using namespace nephele;
using namespace nephele::glsl;

namespace {

constexpr float kUlp = 1.0f / 16777216.0f;

model::CloudModel with_blend(model::CloudModel m, model::Blend blend) {
  m.blend = blend;
  return m;
}

}  // namespace

TEST_CASE("Wyvill-1 is 1 within the radius, 1/2 half-way, 0 at and beyond the influence edge", "[fast][model]") {
  CHECK(wyvill1(-0.5f) == 1.0f);
  CHECK(wyvill1(0.0f) == 1.0f);
  // -4/9 / 64 + 17/9 / 16 - 22/9 / 4 + 1 = (-4 + 68 - 352 + 576) / 576 = 1/2 exactly; the
  // three float roundings of Horner's scheme on values below 3 stay within 4 ulp.
  CHECK(std::abs(wyvill1(0.5f) - 0.5f) <= 4 * kUlp);
  CHECK(wyvill1(1.0f) == 0.0f);
  CHECK(wyvill1(1.5f) == 0.0f);
  ModelPrimitive p;
  p.a = vec4(0.5f, 0.5f, 0.5f, 0.1f);
  p.b = vec4(0.5f, 0.5f, 0.5f, 0.2f);
  p.kind = vec4(0.8f, float(MODEL_POINT), 0.0f, 0.0f);
  CHECK(primitive_field(vec3(0.55f, 0.5f, 0.5f), p) == 0.8f);  // inside R: g = w
  CHECK(primitive_field(vec3(0.5f, 0.5f, 0.81f), p) == 0.0f);  // beyond R + I
}

TEST_CASE("Wyvill-1's first derivative is continuous (zero) at the skeleton radius and the influence edge",
          "[fast][model]") {
  // One-sided difference quotients over h: b'(0) = b'(1) = 0, so they are bounded by
  // max|b''| h / 2 (|b''| <= 44/9 near 0 and 40/9 near 1) plus two roundings of values below
  // 1 divided by h. Outside [0, 1] b is constant, so the quotients there are exactly 0.
  const float h = 1.0f / 64.0f;
  const float bound = 44.0f / 9.0f * h / 2.0f + 2.0f * kUlp / h;
  CHECK(std::abs((wyvill1(h) - wyvill1(0.0f)) / h) <= bound);
  CHECK(std::abs((wyvill1(1.0f) - wyvill1(1.0f - h)) / h) <= bound);
  CHECK((wyvill1(0.0f) - wyvill1(-h)) / h == 0.0f);
  CHECK((wyvill1(1.0f + h) - wyvill1(1.0f)) / h == 0.0f);
  // Interior slopes are not 0 (the test would pass for a constant): b'(1/2) = -1.5833.
  CHECK((wyvill1(0.5f + h) - wyvill1(0.5f - h)) / (2 * h) < -1.5f);
}

TEST_CASE("Lipus's blend stays within the weight and does not depend on the order of primitives", "[fast][model]") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int trial = 0; trial < 200; ++trial) {
    const float w = 0.05f + 0.95f * unit(rng);
    std::vector<float> g(1 + trial % 12);
    for (float& v : g) v = w * unit(rng);
    auto blend = [&](const std::vector<float>& values) {
      float rho = 0.0f;
      for (float v : values) rho = lipus_blend(rho, v, w);
      return rho;
    };
    const float forward = blend(g);
    std::vector<float> shuffled = g;
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    // Each blend rounds 4 times on values below w: 4 ulp of w per primitive, both orders.
    const float rounding = 2 * 4 * float(g.size()) * kUlp * w;
    INFO("w " << w << ", " << g.size() << " primitives");
    CHECK(forward <= w * (1.0f + 4 * kUlp * float(g.size())));
    CHECK(forward >= *std::max_element(g.begin(), g.end()) - rounding);
    CHECK(std::abs(forward - blend(shuffled)) <= rounding);
  }
}

TEST_CASE("with one primitive, turbulence per primitive (eq. 6) equals global turbulence (eq. 5)", "[fast][model]") {
  model::CloudModel m = model::example("fair-weather");
  m.primitives.resize(1);
  m.primitives[0].noise = m.noise;
  std::mt19937 rng(6);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  int inside = 0;
  for (int k = 0; k < 2000; ++k) {
    const vec3 p(0.3f + 0.4f * unit(rng), 0.3f + 0.4f * unit(rng), 0.2f + 0.4f * unit(rng));
    const float global = model::density_at(with_blend(m, model::Blend::global), p);
    const float per_primitive = model::density_at(with_blend(m, model::Blend::per_primitive), p);
    // rho_1 = g_1 exactly (0 + g - 0 g / w), so both apply (1 - np) g + np g N to the same g.
    CHECK(global == per_primitive);
    inside += global > 0.0f;
  }
  CHECK(inside > 100);  // the points probe the cloud, not only empty space
}

TEST_CASE("a primitive's footprint holds every brick where its field is non-zero", "[fast][model]") {
  const model::BrickGrid grid{40};
  for (const auto& name : model::example_names()) {
    const model::CloudModel m = model::example(name);
    const auto lists = model::brick_lists(grid, m);
    for (int z = 0; z < grid.size; ++z)
      for (int y = 0; y < grid.size; ++y)
        for (int x = 0; x < grid.size; ++x) {
          const vec3 p = (vec3(ivec3(x, y, z)) + 0.5f) / float(grid.size);
          const int n = grid.per_axis();
          const auto& list = lists[size_t(x / 8 + n * (y / 8 + n * (z / 8)))];
          for (size_t i = 0; i < m.primitives.size(); ++i)
            if (primitive_field(p, model::pack(m.primitives[i])) > 0.0f) {
              INFO(name << " primitive " << i << " voxel " << x << " " << y << " " << z);
              REQUIRE(std::find(list.begin(), list.end(), std::uint32_t(i)) != list.end());
            }
        }
  }
}

TEST_CASE("brick culling gives the same volume as brute force, bit for bit, in every blend", "[model][gpu]") {
  test::test_context();
  // 44 voxels: bricks at the far faces are cut (44 = 5 x 8 + 4).
  model::DensityVolume culled(44), brute(44);
  for (const auto& name : model::example_names())
    for (auto blend : {model::Blend::sum, model::Blend::lipus, model::Blend::global, model::Blend::per_primitive}) {
      const model::CloudModel m = with_blend(model::example(name), blend);
      culled.compute(m, true);
      brute.compute(m, false);
      INFO(name << " " << model::blend_name(blend));
      CHECK(culled.stats().bricks_computed < brute.stats().bricks_computed);
      const auto a = culled.read(), b = brute.read();
      CHECK(a == b);
      CHECK(*std::max_element(a.begin(), a.end()) > 0.1f);
    }
}

TEST_CASE("editing one primitive recomputes only its old and new footprints and equals a full recompute",
          "[model][gpu]") {
  test::test_context();
  const int size = 48;
  const model::BrickGrid grid{size};
  model::CloudModel m = model::example("cumulonimbus");
  model::DensityVolume edited(size), full(size);
  edited.compute(m);
  for (int index : {0, 3, 6}) {
    model::Primitive moved = m.primitives[size_t(index)];
    moved.from += vec3(0.07f, -0.05f, 0.03f);
    moved.to += vec3(0.07f, -0.05f, 0.03f);
    moved.radius *= 1.2f;
    moved.noise.seed += 100;
    auto before = model::footprint(grid, m.primitives[size_t(index)]);
    auto after = model::footprint(grid, moved);
    before.insert(before.end(), after.begin(), after.end());
    std::sort(before.begin(), before.end());
    before.erase(std::unique(before.begin(), before.end()), before.end());
    edited.edit(index, moved);
    m.primitives[size_t(index)] = moved;
    full.compute(m);
    INFO("primitive " << index);
    CHECK(edited.stats().bricks_computed == int(before.size()));
    CHECK(edited.stats().bricks_computed < grid.count() / 2);
    CHECK(edited.read() == full.read());
  }
}

TEST_CASE("the GPU density volume agrees with its CPU twin", "[model][gpu]") {
  test::test_context();
  const int size = 24;
  model::DensityVolume volume(size);
  for (const auto& name : model::example_names()) {
    const model::CloudModel m = model::example(name);
    volume.compute(m);
    const auto gpu = volume.read();
    const auto cpu = model::density_cpu(m, size);
    // As the probe's kBlended (tests/test_library_probes.cpp), with noise coordinates up to
    // L = frequency 0.2 x 2^3 / scale 0.02 = 80: per octave a point of Perlin noise within 16
    // chained operations (16 x 3.5 x 4 ulp) plus a half-ulp move of each of 3 lattice
    // coordinates of size L times the slope 8.5; amplitudes sum below 2, fields below 1, and
    // 10 primitives each add their share; 8 arithmetic roundings per field.
    const float octave = 16 * 3.5f * 4 * kUlp + 3 * 8.5f * 0.5f * 80 * kUlp;
    const float tolerance = 10 * (2 * octave + 8 * 8 * 3.5f * 4 * kUlp);
    float worst = 0;
    for (size_t i = 0; i < gpu.size(); ++i) worst = std::max(worst, std::abs(gpu[i] - cpu[i]));
    INFO(name << ": largest difference " << worst << ", tolerance " << tolerance);
    CHECK(worst <= tolerance);
  }
}

TEST_CASE("each scenes/*.cloud.json holds its built-in example", "[fast][model]") {
  for (const auto& name : model::example_names()) {
    const std::string path = std::string(NEPHELE_SOURCE_DIR) + "/scenes/" + name + ".cloud.json";
    INFO(path);
    REQUIRE(std::filesystem::exists(path));
    CHECK(io::write_cloud_model(io::read_cloud_model(path)) == io::write_cloud_model(model::example(name)));
  }
}

TEST_CASE("unequal weights are refused in the Lipus blends and allowed in the plain sum", "[fast][model]") {
  model::CloudModel m = model::example("towering");
  m.primitives[2].weight = 0.5f;
  CHECK_THROWS_WITH(model::validate(m, "t"), Catch::Contains("primitives[2].weight") && Catch::Contains("one weight"));
  m.blend = model::Blend::sum;
  CHECK_NOTHROW(model::validate(m, "t"));
}

TEST_CASE("the preview pass agrees with its CPU twin and shows the cloud in the middle of the frame", "[model][gpu]") {
  test::test_context();
  const int size = 24;
  const model::CloudModel m = model::example("towering");
  model::DensityVolume volume(size);
  volume.compute(m);
  render::PreviewSettings s;
  s.width = 24;
  s.height = 16;
  s.view_steps = 16;
  s.light_steps = 4;
  const core::ImageData gpu = render::render_preview(volume, s);
  const core::ImageData cpu = render::render_preview_cpu(volume.read(), size, m, s);
  REQUIRE(gpu.pixels.size() == cpu.pixels.size());
  // Positions are formed with up to 4 roundings of coordinates below 4 extents (kMetres). An
  // extinction moves by 0.075 per unit of density, the density by at most 1 per voxel of
  // extent / size, plus the filter's rounding (2^-20). Optical depths along a light ray (4
  // samples) or the view ray cover at most sqrt(3) extents, so each errs by at most
  // extinction x 1.8 extents. The pixel is sum_i T_i (1 - e^(-sigma_i ds)) S_i / sigma_i with
  // sum_i T_i (1 - e^(-sigma_i ds)) <= 1 and sources S / sigma below the radiance scale 4; a
  // source changes by at most its light depth's error relative (d/dtau e^(-b tau) with b <= 1),
  // the weights by the view depth's error: 4 x (2 depth errors).
  const float extent = float(m.extent_m);
  const float kMetres = 4 * 4 * extent * kUlp;
  const float extinction = 0.075f * (kMetres / (extent / size) + 16 * kUlp);
  const float depth = extinction * 1.8f * extent;
  const float tolerance = 4 * (2 * depth) + 1e-5f;
  float worst = 0;
  for (size_t i = 0; i < gpu.pixels.size(); ++i) worst = std::max(worst, std::abs(gpu.pixels[i] - cpu.pixels[i]));
  INFO("largest difference " << worst << ", tolerance " << tolerance);
  CHECK(worst <= tolerance);
  auto alpha = [&](int x, int y) { return gpu.pixels[(size_t(y) * s.width + x) * 4 + 3]; };
  CHECK(alpha(s.width / 2, s.height / 2) > 0.9f);  // the column, seen through its middle
  CHECK(alpha(0, 0) == 0.0f);                      // the sky beside the box
}

TEST_CASE("the gradient noise's mean absolute value is the PERLIN_MEAN_ABS that replaces faded octaves",
          "[fast][model]") {
  // 200000 points: the standard error is sd(|n|) / sqrt(n) = 0.156 / 447 = 3.5e-4; 4 of them.
  std::mt19937 rng(12);
  std::uniform_real_distribution<float> u(-500.0f, 500.0f);
  const int n = 200000;
  double sum = 0;
  for (int i = 0; i < n; ++i)
    sum += std::abs(perlin_noise(vec3(u(rng), u(rng), u(rng)), ivec3(0), uvec3(std::uint32_t(i % 31), 1u, 2u)));
  CHECK(std::abs(sum / n - PERLIN_MEAN_ABS) < 4 * 3.5e-4);
}

TEST_CASE("erosion gives a point's outline lobes between R and R + I where eq. 6 alone keeps the ball R + I",
          "[fast][model]") {
  model::CloudModel m;
  m.primitives = {model::Primitive{}};
  model::Primitive& p = m.primitives[0];
  p.radius = 0.1f;
  p.influence = 0.15f;
  // The outline along direction u: where the density last exceeds 0, found by stepping out.
  auto outline = [&](vec3 u) {
    float last = 0.0f;
    for (float r = 0.0f; r <= 0.3f; r += 0.0005f)
      if (model::density_at(m, vec3(0.5f) + r * u) > 0.0f) last = r;
    return last;
  };
  std::mt19937 rng(3);
  std::normal_distribution<float> g;
  std::vector<vec3> directions;
  for (int i = 0; i < 200; ++i) directions.push_back(normalize(vec3(g(rng), g(rng), g(rng))));
  // e = 0: eq. 6 scales the field, whose support is the ball R + I (to the step of 0.0005).
  p.noise.erosion = 0.0f;
  for (const vec3& u : directions) CHECK(outline(u) == Approx(0.25f).margin(0.0006f));
  // e = 1/2, np = 1/2: where N = 0 the field (1 - np) b(x) must exceed k = e, so b(x) = 1 and the
  // outline is at R; where N >= 1 nothing is eroded and it stays at R + I. Over 200 directions
  // the outline must span at least a quarter of I and stay within [R, R + I].
  p.noise.erosion = 0.5f;
  float lowest = 1, highest = 0;
  for (const vec3& u : directions) {
    const float r = outline(u);
    lowest = std::min(lowest, r);
    highest = std::max(highest, r);
  }
  INFO("outline from " << lowest << " to " << highest);
  CHECK(lowest >= 0.1f - 0.0006f);
  CHECK(highest <= 0.25f + 0.0006f);
  CHECK(highest - lowest >= 0.25f * 0.15f);
}

TEST_CASE("the examples' bases are flat at the condensation level and the cumulonimbus's top at the tropopause",
          "[model][gpu]") {
  test::test_context();
  const int size = 64;
  model::DensityVolume volume(size);
  for (const auto& name : model::example_names()) {
    const model::CloudModel m = model::example(name);
    volume.compute(m);
    const auto v = volume.read();
    auto at = [&](int x, int y, int z) { return v[(size_t(z) * size + y) * size + x]; };
    // Voxel centres (z + 0.5) / size: none below the base or above the top holds cloud.
    const float voxel = 1.0f / size;
    // Columns whose cloud starts in the lower half (the towers') and ends in the upper half.
    int low = 0, high = 0, on_base = 0, under_top = 0;
    const float middle = 0.5f * (m.base + m.top);
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        int bottom = -1, top = -1;
        for (int z = 0; z < size; ++z)
          if (at(x, y, z) > 0.05f) {
            if (bottom < 0) bottom = z;
            top = z;
          }
        if (bottom < 0) continue;
        const float zb = (bottom + 0.5f) * voxel, zt = (top + 0.5f) * voxel;
        INFO(name << " column " << x << " " << y << " from " << zb << " to " << zt);
        REQUIRE(zb >= m.base);
        REQUIRE(zt <= m.top);
        // The density reaches 0.05 within the smoothstep's edge (0.01) and a voxel of the base.
        if (zb < middle) {
          ++low;
          on_base += zb <= m.base + glsl::MODEL_LEVEL_EDGE + voxel;
        }
        if (zt > middle) {
          ++high;
          under_top += zt >= m.top - glsl::MODEL_LEVEL_EDGE - voxel;
        }
      }
    INFO(name << ": " << low << " columns from the lower half, " << on_base << " of them on the base; " << high
              << " to the upper half, " << under_top << " of them at the top");
    // A flat base: most towers' columns start at the condensation level (the rest are their
    // rounded flanks); most of the anvil's columns end at the tropopause.
    CHECK(low > 0);
    CHECK(on_base >= low / 2);
    if (name == "cumulonimbus") CHECK(under_top >= high / 2);
  }
}
