#include "studies/benchmarks.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>

#include "cover/equirect.hpp"
#include "cover/global_cover.hpp"
#include "gpu/pass_timer.hpp"
#include "files/image_files.hpp"
#include "model/density_volume.hpp"

namespace nephele::studies {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

namespace {

// Encodes the faces and the equirect map of the cover channel as float32 ZIP EXR in memory, in
// parallel (generate's default files hold two channels more); returns the bytes.
double encode_cover_images(const std::vector<float>& texels, const std::vector<float>& equirect, int size) {
  std::vector<std::future<size_t>> jobs;
  const size_t per_face = static_cast<size_t>(size) * size;
  for (int face = 0; face < 6; ++face)
    jobs.push_back(std::async(std::launch::async, [&, face] {
      const core::ImageData image{
          size, size, 1, std::vector<float>(texels.begin() + face * per_face, texels.begin() + (face + 1) * per_face)};
      return files::encode_image(image, files::exr_encoding({"Y"}), "face").size();
    }));
  jobs.push_back(std::async(std::launch::async, [&] {
    return files::encode_image(core::ImageData{4 * size, 2 * size, 1, equirect}, files::exr_encoding({"Y"}), "equirect")
        .size();
  }));
  double bytes = 0;
  for (auto& job : jobs) bytes += static_cast<double>(job.get());
  return bytes;
}

noise::TextureSpec single(int size, noise::NoiseType type, int cells, int octaves) {
  noise::TextureSpec spec;
  spec.width = spec.height = spec.depth = size;
  spec.channels[0].type = type;
  spec.channels[0].cells = cells;
  spec.channels[0].octaves = octaves;
  return spec;
}

}  // namespace

const std::vector<std::string>& cover_bench_passes() {
  static const std::vector<std::string> passes = {"identity",  "spline",   "curl",     "warp",    "density",
                                                  "calibrate", "coverage", "diagnose", "equirect"};
  return passes;
}

CoverBenchRow bench_cover_size(cover::CoverParameters parameters, int size, int repeat) {
  parameters.size = size;
  const auto& passes = cover_bench_passes();
  std::vector<std::vector<double>> device(passes.size());
  std::vector<double> wall, read, encode, megabytes;
  CoverBenchRow row;
  row.size = size;
  {
    cover::GlobalCover first(parameters);
    gpu::PassTimer whole;
    first.run();
    first.diagnose();
    row.first_ms = whole.milliseconds();
  }
  for (int r = 0; r < repeat; ++r) {
    cover::GlobalCover cover(parameters);
    gpu::PassTimer whole;
    cover.run();
    cover.diagnose();
    for (const auto& t : cover.timings())
      for (size_t k = 0; k < passes.size(); ++k)
        if (t.pass == passes[k]) {
          device[k].push_back(t.device_milliseconds > 0 ? t.device_milliseconds : t.milliseconds);
          if (t.device_milliseconds <= 0 && t.milliseconds > 0) row.wall_fallback = true;
        }
    std::vector<float> equirect;
    gpu::DeviceTimer equirect_device;
    const double equirect_wall = gpu::time_pass(
        [&] { equirect = cover::equirect_from_cube(cover.cover_field(), 4 * size, 2 * size, 0, &equirect_device); });
    // Without device time, the wall clock of the resampling includes its read-back.
    const double equirect_ms = equirect_device.milliseconds();
    device.back().push_back(equirect_ms > 0 ? equirect_ms : equirect_wall);
    wall.push_back(whole.milliseconds());
    std::vector<float> texels;
    read.push_back(gpu::time_pass([&] { texels = cover.cover_field().read(); }));
    const auto start = std::chrono::steady_clock::now();
    const double bytes = encode_cover_images(texels, equirect, size);
    encode.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    megabytes.push_back(bytes / 1e6);
  }
  // A pass the parameters do not run (spline outside curl mode spline) costs nothing.
  for (auto& d : device) row.device_ms.push_back(d.empty() ? 0.0 : median(d));
  row.wall_ms = median(wall);
  row.read_ms = median(read);
  row.encode_ms = median(encode);
  row.megabytes = median(megabytes);
  return row;
}

NoiseRun measure_noise(noise::TextureGenerator& generator, const noise::TextureSpec& spec, int repeat) {
  NoiseRun run;
  noise::Volume volume;
  run.first_ms = gpu::time_pass([&] { generator.generate(spec, volume); });
  std::vector<double> compute, device, total;
  for (int r = 0; r < repeat; ++r) {
    total.push_back(gpu::time_pass([&] { generator.generate(spec, volume); }));
    compute.push_back(generator.timings().compute_ms);
    device.push_back(generator.timings().device_ms);
  }
  run.compute_ms = median(compute);
  run.device_ms = median(device);
  run.total_ms = median(total);
  return run;
}

std::vector<NoiseBenchCase> noise_bench_cases(int size) {
  using noise::NoiseType;
  return {
      {"Worley F1, 8 cells (16 texels/cell)", single(size, NoiseType::worley, std::max(1, size / 16), 1)},
      {"Worley F1, 32 cells (4 texels/cell)", single(size, NoiseType::worley, std::max(1, size / 4), 1)},
      {"Perlin, 8 cells", single(size, NoiseType::perlin, std::max(1, size / 16), 1)},
      {"Perlin, 32 cells", single(size, NoiseType::perlin, std::max(1, size / 4), 1)},
      {"Perlin fBm 4 octaves, 8..64 cells", single(size, NoiseType::perlin, std::max(1, size / 16), 4)},
      {"Worley F1 fBm 4 octaves, 8..64 cells", single(size, NoiseType::worley, std::max(1, size / 16), 4)},
  };
}

model::CloudModel spiral_of_cumuli(int n, model::Blend blend) {
  model::CloudModel m;
  m.blend = blend;
  for (int i = 0; i < n; ++i) {
    model::Primitive p;
    const float r = 0.3f * std::sqrt((float(i) + 0.5f) / float(n)), angle = 2.39996323f * float(i);
    p.from = p.to = glsl::vec3(0.5f + r * std::cos(angle), 0.5f + r * std::sin(angle), 0.35f + 0.05f * float(i % 3));
    p.radius = 0.05f;
    p.influence = 0.08f;
    p.noise.seed = std::uint32_t(i + 1);
    m.primitives.push_back(p);
  }
  return m;
}

ModelBenchRow bench_model_case(model::DensityVolume& volume, int primitives, model::Blend blend, int repeat) {
  const int size = volume.size();
  const model::CloudModel m = spiral_of_cumuli(primitives, blend);
  volume.compute(m);  // warming: compiles and allocates
  ModelBenchRow row;
  row.primitives = primitives;
  row.blend = blend;
  std::vector<double> full, edit;
  for (int r = 0; r < repeat; ++r) {
    volume.compute(m);
    full.push_back(volume.stats().ms);
    row.full_occupancy = volume.stats().occupancy();
    // Moves the first primitive by one brick's width and back: two edits, each timed.
    model::Primitive moved = m.primitives[0];
    moved.from += glsl::vec3(8.0f / float(size), 0.0f, 0.0f);
    moved.to = moved.from;
    volume.edit(0, moved);
    edit.push_back(volume.stats().ms);
    row.edit_occupancy = volume.stats().occupancy();
    volume.edit(0, m.primitives[0]);
    edit.push_back(volume.stats().ms);
  }
  row.full_ms = median(full);
  row.edit_ms = median(edit);
  return row;
}

}  // namespace nephele::studies
