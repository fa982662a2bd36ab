#include "cover/global_cover.hpp"

#include <chrono>

namespace nephele::cover {

void set_uniform(const gl::ComputeProgram& program, const std::string& name,
                 const glsl::FbmParams& params) {
  program.set(name + ".frequency", params.frequency);
  program.set(name + ".octaves", params.octaves);
  program.set(name + ".lacunarity", params.lacunarity);
  program.set(name + ".gain", params.gain);
  program.set(name + ".seed", static_cast<unsigned>(params.seed));
  // The sphere's noise is not periodic; the linker may drop an unused member.
  if (program.has_uniform(name + ".period")) program.set(name + ".period", params.period);
}

void set_uniform(const gl::ComputeProgram& program, const std::string& name,
                 const glsl::CurlParams& params) {
  set_uniform(program, name + ".potential_north", params.potential_north);
  set_uniform(program, name + ".potential_south", params.potential_south);
  program.set(name + ".prevailing", params.prevailing);
  program.set(name + ".mix_frequency", params.mix_frequency);
  program.set(name + ".strength", params.strength);
}

double cover_gpu_bytes(int size) {
  const double texels = 6.0 * size * size;
  const double cubes = texels * (16.0 * 3 + 4.0 * 2);  // identity, curl, warp; density, cover
  const double equirect = 8.0 * size * size * 4.0;
  return cubes + equirect;
}

GlobalCover::GlobalCover(const CoverParameters& parameters)
    : parameters_(parameters),
      identity_field_(gl::Texture::cube(parameters.size, GL_RGBA32F)),
      curl_field_(gl::Texture::cube(parameters.size, GL_RGBA32F)),
      warp_field_(gl::Texture::cube(parameters.size, GL_RGBA32F)),
      density_field_(gl::Texture::cube(parameters.size, GL_R32F)),
      cover_field_(gl::Texture::cube(parameters.size, GL_R32F)) {}

template <class Work>
void GlobalCover::timed(const std::string& pass, Work&& work) {
  glFinish();
  const auto start = std::chrono::steady_clock::now();
  work();
  glFinish();
  const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;
  timings_.push_back({pass, elapsed.count()});
}

void GlobalCover::run() {
  run_identity();
  run_curl();
  run_warp();
  run_density();
  run_coverage();
}

void GlobalCover::run_identity() {
  timed("identity", [&] {
    identity_field_.bind_image(0, GL_WRITE_ONLY);
    identity_program_.dispatch_covering(parameters_.size, parameters_.size, 6);
    gl::image_barrier();
  });
}

void GlobalCover::run_curl() {
  timed("curl", [&] {
    set_uniform(curl_program_, "u_curl", curl_params(parameters_));
    identity_field_.bind_image(0, GL_READ_ONLY);
    curl_field_.bind_image(1, GL_WRITE_ONLY);
    curl_program_.dispatch_covering(parameters_.size, parameters_.size, 6);
    gl::image_barrier();
  });
}

void GlobalCover::run_warp() {
  timed("warp", [&] {
    warp_program_.set("u_steps", parameters_.iterations);
    warp_program_.set("u_step_size", parameters_.step);
    identity_field_.bind_image(0, GL_READ_ONLY);
    curl_field_.bind_image(1, GL_READ_ONLY);
    warp_field_.bind_image(2, GL_WRITE_ONLY);
    warp_program_.dispatch_covering(parameters_.size, parameters_.size, 6);
    gl::image_barrier();
  });
}

void GlobalCover::run_density() {
  timed("density", [&] {
    set_uniform(density_program_, "u_cover", density_params(parameters_));
    warp_field_.bind_image(0, GL_READ_ONLY);
    density_field_.bind_image(1, GL_WRITE_ONLY);
    density_program_.dispatch_covering(parameters_.size, parameters_.size, 6);
    gl::image_barrier();
  });
}

CoverageCalibration GlobalCover::run_coverage() {
  timed("calibrate", [&] {
    calibration_ = calibrate_coverage(density_field_.read(), parameters_.size, parameters_.coverage);
  });
  timed("coverage", [&] {
    remap_program_.set("u_threshold", calibration_.threshold);
    remap_program_.set("u_density_max", calibration_.density_max);
    density_field_.bind_image(0, GL_READ_ONLY);
    cover_field_.bind_image(1, GL_WRITE_ONLY);
    remap_program_.dispatch_covering(parameters_.size, parameters_.size, 6);
    gl::image_barrier();
  });
  return calibration_;
}

}  // namespace nephele::cover
