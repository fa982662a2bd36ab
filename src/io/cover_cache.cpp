#include "io/cover_cache.hpp"

#include "core/hash.hpp"
#include "core/json.hpp"
#include "cover/global_cover.hpp"
#include "files/float_cache.hpp"
#include "gpu/pass_timer.hpp"
#include "io/cover_files.hpp"

namespace nephele::io {

std::string cover_cache_key(const cover::CoverParameters& parameters) {
  std::string key = "global_cover 1 " + json::write(cover_parameters_json(cover::resolved_curl(parameters)));
  if (parameters.surface) {
    const std::vector<float>& land = parameters.surface->land;
    key += " mask " + std::to_string(parameters.surface->columns) + "x" + std::to_string(parameters.surface->rows) +
           " " + core::hex_digits(core::block_hash(land.data(), land.size() * sizeof(float)));
  }
  for (const std::vector<double>* knots : {&parameters.profile.latitude_deg, &parameters.profile.fraction})
    key += " profile " + core::hex_digits(core::block_hash(knots->data(), knots->size() * sizeof(double)));
  return key + " program " + files::program_fingerprint();
}

render::GlobalCoverFaces cached_global_cover(const cover::CoverParameters& parameters,
                                             const std::filesystem::path& directory, std::string* note) {
  render::GlobalCoverFaces faces;
  std::string what;
  const double ms = gpu::time_pass([&] {
    const std::string program = files::program_fingerprint();
    if (directory.empty() || program.empty()) {
      faces = render::make_global_cover(parameters);
      what = directory.empty() ? "global cover: made (no cache)"
                               : "global cover: made (no cache: the program's own file cannot be read)";
      return;
    }
    const files::FloatCache cache(directory);
    const std::string key = cover_cache_key(parameters);
    const std::size_t texels = 6 * static_cast<std::size_t>(parameters.size) * parameters.size;
    // The three fields one after another in one entry: cover, optical thickness, cloud top.
    if (auto values = cache.load(key, 3 * texels)) {
      faces.size = parameters.size;
      faces.texels.assign(values->begin(), values->begin() + static_cast<std::ptrdiff_t>(texels));
      faces.optical_thickness.assign(values->begin() + static_cast<std::ptrdiff_t>(texels),
                                     values->begin() + static_cast<std::ptrdiff_t>(2 * texels));
      faces.cloud_top.assign(values->begin() + static_cast<std::ptrdiff_t>(2 * texels), values->end());
      what = "global cover: from the cache " + cache.file_of(key).string();
      return;
    }
    faces = render::make_global_cover(parameters);
    std::vector<float> values;
    values.reserve(3 * texels);
    for (const std::vector<float>* field : {&faces.texels, &faces.optical_thickness, &faces.cloud_top})
      values.insert(values.end(), field->begin(), field->end());
    what = values.size() == 3 * texels && cache.store(key, values)
               ? "global cover: made and cached in " + cache.file_of(key).string()
               : "global cover: made (the cache " + directory.string() + " could not be written)";
  });
  if (note != nullptr) *note = what + " (" + std::to_string(ms) + " ms)";
  return faces;
}

}  // namespace nephele::io
