#include "io/cover_files.hpp"

#include <algorithm>
#include <chrono>
#include <exception>
#include <filesystem>
#include <future>
#include <memory>
#include <stdexcept>

#include "files/atomic_output.hpp"
#include "cover/equirect.hpp"
#include "files/image_files.hpp"
#include "core/error.hpp"
#include "nephele/version.hpp"
#include "params/table.hpp"

namespace nephele::io {
namespace {

// A sidecar value: the seed as an unsigned integer, other numbers as they are.
json::Value json_number(std::uint32_t v) { return json::Value(static_cast<unsigned long>(v)); }
template <class T>
json::Value json_number(T v) {
  return json::Value(v);
}

// Sets "a.b" in nested objects, creating "a" at its first use (so the order of first uses stays).
void set_path(json::Value& object, const std::string& path, json::Value value) {
  const auto dot = path.find('.');
  if (dot == std::string::npos) {
    object.set(path, std::move(value));
    return;
  }
  const std::string head = path.substr(0, dot);
  json::Value inner = object.find(head) ? *object.find(head) : json::Value();
  set_path(inner, path.substr(dot + 1), std::move(value));
  object.set(head, std::move(inner));
}

json::Value conventions_json() {
  json::Value c;
  c.set("world_axes",
        "Earth-centred, Earth-fixed: +Z north pole, +X latitude 0 longitude 0, +Y latitude 0 "
        "longitude 90 E");
  c.set("cube_faces",
        "OpenGL 4.6 core section 8.13 table 8.19 applied to world axes: cover_px.exr is face +X, "
        "then -X, +Y, -Y, +Z (north), -Z (south); texel (i, j) has s = (i + 0.5)/N, "
        "t = (j + 0.5)/N; image row 0 is t = 0");
  c.set("equirect",
        "2:1 plate carree, north up, longitude -180 deg at the left edge and 0 at the centre, "
        "pixel centres at (i + 0.5)/W; rows are WGS84 geodetic latitudes");
  c.set("values", "coverage in [0, 1], linear data (no sRGB); 0 is clear sky, > 0 cloudy");
  c.set("channels",
        "EXR channels Y (coverage), tau (optical thickness at 0.6 um, log-normal over the cloudy texels) and "
        "cloud_top (cloud-top height, km above sea level); tau and cloud_top are 0 where Y is 0");
  c.set("png_preview", "8-bit, round(255 * coverage), no gamma curve");
  return c;
}

}  // namespace

void parse_cover_files(const std::string& list, CoverFileOptions& options) {
  const std::string allowed = "a comma-separated non-empty subset of faces, equirect, png";
  options.faces = options.equirect = options.preview = false;
  size_t start = 0;
  while (true) {
    const size_t comma = list.find(',', start);
    const std::string item = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    bool* flag = item == "faces"      ? &options.faces
                 : item == "equirect" ? &options.equirect
                 : item == "png"      ? &options.preview
                                      : nullptr;
    if (!flag || *flag) throw core::InputError(params::run::cover_files.option(), list, allowed);
    *flag = true;
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
}

std::vector<std::string> cover_file_names(const CoverFileOptions& options) {
  std::vector<std::string> names;
  if (options.faces)
    for (const char* suffix : face_suffixes) names.push_back(std::string("cover_") + suffix + ".exr");
  if (options.equirect) names.push_back("cover_equirect.exr");
  if (options.preview) names.push_back("cover_equirect.png");
  names.push_back("cover.json");
  return names;
}

json::Value cover_parameters_json(const cover::CoverParameters& p) {
  // Keys and nesting come from the parameter table (sidecar paths such as "potential.gain").
  json::Value parameters;
  const bool adaptive = p.integrator == cover::Integrator::adaptive;
  cover::visit_numeric_parameters(p, [&](const params::Parameter& parameter, const auto& value) {
    if (!parameter.used_by(params::cover_sidecar)) return;
    if (!adaptive && (&parameter == &params::cover::tolerance || &parameter == &params::cover::max_substeps)) return;
    if (p.curl_mode != cover::CurlMode::spline && &parameter == &params::cover::curl_size) return;
    if (p.flow == cover::Flow::steady &&
        (&parameter == &params::cover::vortex_lifetime || &parameter == &params::cover::loop ||
         &parameter == &params::cover::warp_grid || &parameter == &params::cover::noise_grid_nodes))
      return;
    set_path(parameters, std::string(parameter.sidecar_path()), json_number(value));
    if (&parameter == &params::cover::coverage) parameters.set(std::string(params::cover::profile.key), p.profile.name);
    if (&parameter == &params::cover::surface_weight)
      parameters.set(std::string(params::cover::surface.key), p.surface ? p.surface->source : "none");
    if (&parameter == &params::cover::step) {
      parameters.set("flow_time", static_cast<double>(p.iterations) * p.step);
      parameters.set(std::string(params::cover::integrator.key), cover::integrator_name(p.integrator));
      parameters.set(std::string(params::cover::curl_mode.key), cover::curl_mode_name(p.curl_mode));
      parameters.set(std::string(params::cover::flow.key), cover::flow_name(p.flow));
      if (p.flow == cover::Flow::moving) parameters.set(std::string(params::cover::time.key), p.time);
    }
  });
  return parameters;
}

CoverSummary cover_summary(const cover::GlobalCover& cover) {
  CoverSummary s;
  s.parameters = cover.parameters();
  s.calibration = cover.calibration();
  s.bands = cover.band_calibration();
  s.diagnostics = cover.diagnostics();
  s.timings = cover.timings();
  return s;
}

json::Value cover_sidecar(const cover::GlobalCover& cover, const gpu::ContextInfo& context,
                          const std::vector<cover::PassTiming>& export_timings, const CoverFileOptions& options) {
  return cover_sidecar(cover_summary(cover), context, export_timings, options);
}

json::Value cover_sidecar(const CoverSummary& cover, const gpu::ContextInfo& context,
                          const std::vector<cover::PassTiming>& export_timings, const CoverFileOptions& options) {
  const json::Value parameters = cover_parameters_json(cover.parameters);

  const cover::CoverageCalibration& c = cover.calibration;
  json::Value result;
  result.set("cloud_fraction", c.achieved_fraction);
  result.set("cloud_fraction_tolerance", c.max_texel_fraction);
  // One threshold (--profile flat), or the latitude profile's bands (docs/climate.md).
  if (const auto& bands = cover.bands) {
    json::Value profile;
    const double band_deg = 180.0 / static_cast<double>(bands->targets.size());
    profile.set("bands", static_cast<double>(bands->targets.size()));
    profile.set("band_degrees", band_deg);
    profile.set("first_band_south_edge_deg", -90.0);
    json::Value::Array targets, achieved, thresholds;
    for (size_t b = 0; b < bands->targets.size(); ++b) {
      targets.emplace_back(bands->targets[b]);
      achieved.emplace_back(bands->achieved[b]);
      thresholds.emplace_back(static_cast<double>(bands->thresholds[b]));
    }
    profile.set("targets", targets);
    profile.set("achieved", achieved);
    profile.set("thresholds", thresholds);
    result.set("profile", profile);
  } else {
    result.set("threshold", c.threshold);
  }
  result.set("density_min", c.density_min);
  result.set("density_max", c.density_max);

  // Stability of the warp (docs/numerics.md): present when the cover was diagnosed.
  if (const auto& d = cover.diagnostics) {
    json::Value stiffness;
    stiffness.set("max_rate", d->stiffness.max_rate);
    stiffness.set("stiffness_number", d->stiffness.stiffness);
    stiffness.set("stable_limit", d->stiffness.limit);
    stiffness.set("beyond_limit_fraction", d->stiffness.beyond_fraction);
    json::Value folding;
    folding.set("folded_fraction", d->folding.folded_fraction);
    folding.set("jacobian_min", d->folding.jacobian_min);
    folding.set("jacobian_max", d->folding.jacobian_max);
    folding.set("area_error_rms", d->folding.area_error_rms);
    json::Value numerics;
    numerics.set("stiffness", stiffness);
    numerics.set("folding", folding);
    if (d->adaptive) {
      json::Value substeps;
      substeps.set("mean", d->substeps.mean_attempts);
      substeps.set("max", d->substeps.max_attempts);
      substeps.set("capped_texels", static_cast<double>(d->substeps.capped_texels));
      numerics.set("substeps", substeps);
    }
    json::Value::Array warnings;
    for (const auto& w : d->warnings) warnings.emplace_back(w);
    numerics.set("warnings", warnings);
    result.set("numerics", numerics);
  }

  json::Value timings;
  for (const auto& t : cover.timings) timings.set(t.pass, t.milliseconds);
  for (const auto& t : export_timings) timings.set(t.pass, t.milliseconds);

  json::Value device;
  device.set("platform", context.platform);
  device.set("vendor", context.vendor);
  device.set("renderer", context.renderer);
  device.set("version", context.version);

  json::Value files;
  if (options.faces) {
    json::Value::Array faces;
    for (const char* suffix : face_suffixes) faces.emplace_back(std::string("cover_") + suffix + ".exr");
    files.set("faces", faces);
  }
  if (options.equirect) files.set("equirect", "cover_equirect.exr");
  if (options.preview) files.set("preview", "cover_equirect.png");
  // Recorded when they differ from the defaults, so that default sidecars stay as they were.
  if (options.half) files.set("exr_precision", "half");
  if (options.compression != "zip") files.set("exr_compression", options.compression);
  if (cover.tiles > 0) files.set("computed_in_tiles", cover.tiles);

  json::Value root;
  root.set("program", "nephele");
  root.set("version", version);
  root.set("parameters", parameters);
  root.set("result", result);
  root.set("conventions", conventions_json());
  root.set("files", files);
  root.set("device", device);
  root.set("timings_ms", timings);
  return root;
}

std::vector<float> reduced_faces(int size, const std::vector<float>& texels, int reduced) {
  if (reduced >= size) return texels;
  // Each reduced texel is the mean of the texels whose centres fall in it (k x k blocks when
  // the sizes divide, else one or two texels more or less along an edge).
  std::vector<double> sum(6 * static_cast<size_t>(reduced) * reduced, 0.0);
  std::vector<int> count(sum.size(), 0);
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < size; ++j) {
      const int rj = static_cast<int>(static_cast<long>(j) * reduced / size);
      for (int i = 0; i < size; ++i) {
        const int ri = static_cast<int>(static_cast<long>(i) * reduced / size);
        const size_t at = (static_cast<size_t>(face) * reduced + rj) * reduced + ri;
        sum[at] += texels[(static_cast<size_t>(face) * size + j) * size + i];
        ++count[at];
      }
    }
  std::vector<float> out(sum.size());
  for (size_t k = 0; k < out.size(); ++k) out[k] = static_cast<float>(sum[k] / count[k]);
  return out;
}

namespace {

using Clock = std::chrono::steady_clock;

double milliseconds_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

std::vector<float> interleaved_channels(const CoverPlanes& planes, std::size_t first, std::size_t count) {
  constexpr int n = CoverPlanes::count;
  std::vector<float> out(n * count);
  for (int c = 0; c < n; ++c) {
    if (planes[c].size() < first + count) throw std::invalid_argument("interleaved_channels: a plane is too short");
    const float* in = planes[c].data() + first;
    for (std::size_t k = 0; k < count; ++k) out[n * k + c] = in[k];
  }
  return out;
}

files::ImageEncoding cover_exr_encoding(const CoverFileOptions& options) {
  files::ImageEncoding exr = files::exr_encoding(cover_channels, options.half ? 16 : 32, options.compression);
  exr.half_channels = {options.half, true, true};
  return exr;
}

namespace {

// The rows an image file takes at a time: the EXR writer converts each batch to the file's
// channel types, so its buffer is a batch, not the image (64 rows: four of OpenEXR's 16-line
// zip blocks).
constexpr int rows_per_batch = 64;

// Writes a width x height image of `channels` into `path` (fsynced) through a row writer, a batch
// of rows at a time from rows(first_row, count), which returns a pointer to their interleaved
// pixels (valid until the next call); errors name `shown`. Returns the file's size in bytes.
template <class Rows>
std::uintmax_t write_image_rows(const std::filesystem::path& path, const std::string& shown, int width, int height,
                                int channels, const files::ImageEncoding& encoding, Rows rows) {
  files::ImageRowWriter writer(path, width, height, channels, encoding, shown);
  for (int first = 0; first < height; first += rows_per_batch) {
    const int count = std::min(rows_per_batch, height - first);
    writer.write_rows(count, rows(first, count));
  }
  writer.close();
  return std::filesystem::file_size(path);
}

}  // namespace

void write_cover_images(files::OutputSet& outputs, const CoverImages& images, const CoverFileOptions& options,
                        CoverExport& result) {
  const files::ImageEncoding exr = cover_exr_encoding(options);
  // Each image is encoded and written into its place in the output set on its own thread, a
  // batch of rows at a time (the names are reserved here: the set is not shared between
  // threads), so that no image is held twice, as pixels and as encoded bytes.
  std::vector<std::future<std::uintmax_t>> jobs;
  const auto encode_start = Clock::now();
  if (images.faces) {
    const int size = images.face_size;
    const size_t per_face = static_cast<size_t>(size) * size;
    for (int face = 0; face < 6; ++face) {
      const std::string name = std::string("cover_") + face_suffixes[face] + ".exr";
      const std::filesystem::path path = outputs.reserve(name);
      const std::string shown = outputs.final_path(name).string();
      jobs.push_back(std::async(std::launch::async, [path, shown, size, per_face, face, planes = images.faces, exr] {
        std::vector<float> batch;
        return write_image_rows(path, shown, size, size, CoverPlanes::count, exr, [&](int first, int count) {
          batch = interleaved_channels(*planes, face * per_face + static_cast<size_t>(first) * size,
                                       static_cast<size_t>(count) * size);
          return batch.data();
        });
      }));
    }
  }
  // A whole image's rows, interleaved already.
  auto write_whole = [&](const std::string& name, std::shared_ptr<const core::ImageData> image,
                         files::ImageEncoding encoding) {
    const std::filesystem::path path = outputs.reserve(name);
    const std::string shown = outputs.final_path(name).string();
    jobs.push_back(std::async(std::launch::async, [path, shown, image, encoding] {
      const size_t row = static_cast<size_t>(image->width) * image->channels;
      return write_image_rows(path, shown, image->width, image->height, image->channels, encoding,
                              [&](int first, int) { return image->pixels.data() + static_cast<size_t>(first) * row; });
    }));
  };
  if (images.equirect) write_whole("cover_equirect.exr", images.equirect, exr);
  if (images.preview) {
    // zlib level 1: the 4096 x 2048 preview encodes in about half the time of level 6 (the
    // longest single encoding of generate) for an 8 % larger file; the pixels are the same.
    // The average filter on every row instead of libpng's trial of all five: 141 instead of
    // 200 ms at 1024 per face, and a file 0.6 % smaller.
    files::ImageEncoding preview = files::png_encoding(8);
    preview.png_compression_level = 1;
    preview.png_filters = files::png_filter_average;
    write_whole("cover_equirect.png", images.preview, preview);
  }
  // Every job is waited for before the first error is thrown, so that none still writes into
  // the set's directory when the set removes it.
  std::exception_ptr failed;
  for (auto& job : jobs) {
    try {
      result.bytes += static_cast<double>(job.get());
    } catch (...) {
      if (!failed) failed = std::current_exception();
    }
  }
  if (failed) std::rethrow_exception(failed);
  result.timings.push_back({"encode", milliseconds_since(encode_start)});
}

CoverExport write_cover_files(files::OutputSet& outputs, const cover::GlobalCover& cover,
                              const gpu::ContextInfo& context, const CoverFileOptions& options) {
  CoverExport result;
  auto timed = [&](const std::string& name, auto&& work) {
    const auto start = Clock::now();
    work();
    result.timings.push_back({name, milliseconds_since(start)});
  };
  const int size = cover.parameters().size;
  CoverImages images;
  images.face_size = size;
  const bool reduce_preview = options.preview && size > preview_face_limit;
  if (options.faces || reduce_preview) {
    auto faces = std::make_shared<CoverPlanes>();
    timed("read_faces", [&] {
      faces->cover = cover.cover_field().read();
      if (options.faces) {
        faces->optical_thickness = cover.optical_thickness_field().read();
        faces->cloud_top = cover.cloud_top_field().read();
      }
    });
    if (options.faces) images.faces = faces;
    if (reduce_preview)
      timed("preview", [&] { images.preview = std::make_shared<core::ImageData>(preview_image(size, faces->cover)); });
  }
  if (options.equirect || (options.preview && !reduce_preview)) {
    // Resampled once on the GPU, the channels interleaved as the EXR takes them; both files come
    // from this map (the preview, up to its limit, from its cover channel).
    const int width = 4 * size, height = 2 * size;
    const size_t pixels = static_cast<size_t>(width) * height;
    std::vector<float> map;
    timed("equirect", [&] {
      if (options.equirect)
        map = cover::equirect_from_cubes(
            {&cover.cover_field(), &cover.optical_thickness_field(), &cover.cloud_top_field()}, width, height);
      else
        map = cover::equirect_from_cube(cover.cover_field(), width, height);
    });
    if (options.preview && !reduce_preview) {
      std::vector<float> cover_channel;
      if (options.equirect) {
        cover_channel.resize(pixels);
        for (size_t k = 0; k < pixels; ++k) cover_channel[k] = map[CoverPlanes::count * k];
      } else {
        cover_channel = std::move(map);
      }
      images.preview = std::make_shared<core::ImageData>(core::ImageData{width, height, 1, std::move(cover_channel)});
    }
    if (options.equirect)
      images.equirect = std::make_shared<core::ImageData>(
          core::ImageData{width, height, static_cast<int>(cover_channels.size()), std::move(map)});
  }
  write_cover_images(outputs, images, options, result);
  outputs.write("cover.json", json::write(cover_sidecar(cover, context, result.timings, options)));
  outputs.commit();
  return result;
}

core::ImageData preview_image(int size, const std::vector<float>& texels) {
  const int face = std::min(size, preview_face_limit);
  return core::ImageData{4 * face, 2 * face, 1,
                         cover::equirect_from_faces(face, reduced_faces(size, texels, face), 4 * face, 2 * face)};
}

}  // namespace nephele::io
