#include "io/cover_assembly.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#include "core/error.hpp"
#include "cover/equirect.hpp"
#include "cover/gpu_reductions.hpp"
#include "cover/streamed_equirect.hpp"
#include "files/image_files.hpp"
#include "files/scratch_floats.hpp"

namespace nephele::io {
namespace {

using Clock = std::chrono::steady_clock;

double milliseconds_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Adds `ms` to the pass's entry, appending the pass at its first time.
void add_timing(std::vector<cover::PassTiming>& timings, const std::string& pass, double ms) {
  for (cover::PassTiming& t : timings)
    if (t.pass == pass) {
      t.milliseconds += ms;
      return;
    }
  timings.push_back({pass, ms});
}

}  // namespace

double whole_equirect_bytes(int size) {
  const double n2 = double(size) * size;
  const double channels = static_cast<double>(cover_channels.size());
  // The whole cover's fields, a field's cube map on the device, the 4 N x 2 N maps of the fields
  // and the map interleaved, encoded in memory.
  return 6.0 * n2 * 4.0 * (channels + 1.0) + 8.0 * n2 * 4.0 * (2.0 * channels + 1.0);
}

namespace {

// The bytes the assembly holds besides the equirect EXR's: a tile's densities as read and as
// uploaded and its cover read back; the preview's reduced cube (sums, counts, values) and map.
double tile_and_preview_bytes(int size, int tiles, const CoverFileOptions& options) {
  const double n2 = double(size) * size;
  const double tile = 6.0 * n2 / tiles + 2.0 * size;  // owned texels of the largest tile
  // Its densities and cloud tops as read and uploaded, its fields read back and interleaved.
  double bytes = tile * 4.0 * (4.0 + 2.0 * static_cast<double>(cover_channels.size()));
  const double preview_face = std::min(size, preview_face_limit);
  if (options.preview)
    bytes += 6.0 * preview_face * preview_face * (8.0 + 4.0 + 4.0) + 8.0 * preview_face * preview_face * 4.0;
  return bytes;
}

}  // namespace

bool equirect_from_whole_cover(int size, int tiles, const CoverFileOptions& options, double budget) {
  return budget <= 0 || tile_and_preview_bytes(size, tiles, options) + whole_equirect_bytes(size) <= budget;
}

double assembly_host_bytes(int size, int tiles, const CoverFileOptions& options, double budget) {
  double bytes = tile_and_preview_bytes(size, tiles, options);
  // The equirect EXR: from the whole cover where it fits the budget, else a band of the map (its
  // faces are mapped from scratch files, which the kernel pages).
  if (options.equirect)
    bytes += equirect_from_whole_cover(size, tiles, options, budget)
                 ? whole_equirect_bytes(size)
                 : 4.0 * size * 64 * 4.0 * 2.0 * static_cast<double>(cover_channels.size());
  return bytes;
}

void check_assembly_fits(int size, int tiles, const CoverFileOptions& options, double budget) {
  const double host = assembly_host_bytes(size, tiles, options, budget);
  if (budget <= 0 || host <= budget) return;
  throw core::InputError("--memory-budget: the files of a cover of " + std::to_string(size) + " per face in " +
                         std::to_string(tiles) + " tiles hold " +
                         std::to_string(static_cast<long>(std::ceil(host / 1048576.0))) +
                         " MiB at once (a tile's densities and cover, the preview's cube), over the budget of " +
                         std::to_string(static_cast<long>(budget / 1048576.0)) +
                         " MiB; write fewer --files, use more --tiles or raise --memory-budget");
}

std::vector<TilePart> read_all_tile_parts(const std::filesystem::path& directory, const std::string& field) {
  std::error_code error;
  if (!std::filesystem::is_directory(directory, error))
    throw core::InputError(field, directory.string(), "a directory of tile parts (generate --tiles --tile)",
                           "is not a directory");
  const std::filesystem::path first = directory / tile_part_name(0);
  if (!std::filesystem::exists(first, error))
    throw core::InputError(field, directory.string(), "a directory of tile parts (generate --tiles --tile)",
                           "holds no " + tile_part_name(0));
  std::vector<TilePart> parts;
  parts.push_back(read_tile_header(first));
  const int count = parts.front().tile_count;
  std::vector<int> missing;
  for (int index = 1; index < count; ++index) {
    std::optional<TilePart> part = find_tile_part(directory, index, count, parts.front().identity);
    if (part)
      parts.push_back(std::move(*part));
    else
      missing.push_back(index);
  }
  if (!missing.empty()) {
    std::string list;
    for (size_t k = 0; k < missing.size() && k < 20; ++k) list += (k ? ", " : "") + std::to_string(missing[k]);
    if (missing.size() > 20) list += ", ... (" + std::to_string(missing.size()) + " in all)";
    throw core::InputError(field, directory.string(), "every tile of the cover, 0 to " + std::to_string(count - 1),
                           "lacks tiles " + list + " (run generate with --tile for them)");
  }
  return parts;
}

AssembledCover write_assembled_cover(files::OutputSet& outputs, const std::vector<TilePart>& parts,
                                     const cover::CoverParameters& parameters, const gpu::ContextInfo& context,
                                     const CoverFileOptions& options, double budget,
                                     const std::function<void(const std::string&)>& progress) {
  const int size = parameters.size;
  const int count = static_cast<int>(parts.size());
  const cover::CubeTiling tiling{size, count};
  AssembledCover result;
  CoverSummary& summary = result.summary;
  summary.parameters = cover::resolved_curl(parameters);
  summary.tiles = count;
  const auto say = [&](const std::string& step) {
    if (progress) progress(step);
  };

  // What the tiles' passes reduced: the density range, the diagnosis, their times.
  std::pair<float, float> range{INFINITY, -INFINITY};
  cover::DiagnosisSums sums;
  for (const TilePart& part : parts) {
    range.first = std::min(range.first, part.tile.density_min);
    range.second = std::max(range.second, part.tile.density_max);
    sums.add(part.tile.diagnosis);
    for (const cover::PassTiming& t : part.tile.timings) add_timing(summary.timings, t.pass, t.milliseconds);
  }
  summary.diagnostics =
      cover::diagnostics_from_sums(sums, cover::texel_weight_units(size), summary.parameters.integrator,
                                   summary.parameters.step, summary.parameters.flow == cover::Flow::moving);

  cover::TiledCoverage coverage(parameters, tiling);
  const cover::LoadTileDensity load = [&](int index) { return read_tile_densities(parts[static_cast<size_t>(index)]); };
  const cover::LoadTileDensity load_cloud_top = [&](int index) {
    return read_tile_cloud_tops(parts[static_cast<size_t>(index)]);
  };
  const cover::LoadTileDensity load_contrast = [&](int index) {
    return read_tile_cover_contrasts(parts[static_cast<size_t>(index)]);
  };
  say("calibrate");
  auto start = Clock::now();
  coverage.calibrate(range, load);
  add_timing(summary.timings, "calibrate", milliseconds_since(start));

  // Each tile's cover as it comes: rows of a face EXR, and where asked for the whole cover (the
  // equirect EXR) or the preview's reduced cube.
  const files::ImageEncoding exr = cover_exr_encoding(options);
  const int channels = static_cast<int>(cover_channels.size());
  std::unique_ptr<files::ImageRowWriter> face_writer;
  std::shared_ptr<CoverPlanes> whole;
  // The equirect EXR from the whole cover where it fits the budget, else on the CPU from the
  // faces kept in scratch files (cover/streamed_equirect.hpp).
  const bool streamed = options.equirect && !equirect_from_whole_cover(size, count, options, budget);
  if (options.equirect && !streamed) {
    whole = std::make_shared<CoverPlanes>();
    for (int c = 0; c < CoverPlanes::count; ++c) (*whole)[c].resize(6 * static_cast<size_t>(size) * size);
  }
  // Streamed: the fields' faces in scratch files, channel by channel (6 files a channel).
  std::vector<std::unique_ptr<files::ScratchFloats>> scratch_faces;
  if (streamed)
    for (const std::string& channel : cover_channels)
      for (int face = 0; face < 6; ++face)
        scratch_faces.push_back(std::make_unique<files::ScratchFloats>(
            outputs.temporary_directory() / ("scratch_" + channel + "_" + face_suffixes[face])));
  const int preview_face = std::min(size, preview_face_limit);
  const bool reduce_preview = options.preview && !whole;  // (streamed: from the reduced cube)
  std::vector<double> preview_sum;
  std::vector<int> preview_count;
  if (reduce_preview) {
    preview_sum.assign(6 * static_cast<size_t>(preview_face) * preview_face, 0.0);
    preview_count.assign(preview_sum.size(), 0);
  }
  double face_ms = 0.0;
  start = Clock::now();
  coverage.remap(load, load_cloud_top, load_contrast, [&](int index, const CoverPlanes& planes) {
    const cover::CubeRegion region = cover::owned_region(tiling.tile(index));
    say("tile " + std::to_string(index + 1) + " of " + std::to_string(count));
    const std::vector<float>& cover = planes.cover;
    if (streamed)
      for (int c = 0; c < channels; ++c)
        scratch_faces[static_cast<size_t>(c * 6 + region.face)]->append(planes[c].data(), planes[c].size());
    if (options.faces) {
      const auto face_start = Clock::now();
      const std::string name = std::string("cover_") + face_suffixes[region.face] + ".exr";
      if (region.first_row == 0)
        face_writer = std::make_unique<files::ImageRowWriter>(outputs.reserve(name), size, size, channels, exr,
                                                              outputs.final_path(name).string());
      face_writer->write_rows(region.rows, interleaved_channels(planes, 0, cover.size()).data());
      if (region.first_row + region.rows == size) {
        face_writer->close();
        face_writer.reset();
      }
      face_ms += milliseconds_since(face_start);
    }
    const size_t offset = (static_cast<size_t>(region.face) * size + region.first_row) * size;
    if (whole)
      for (int c = 0; c < channels; ++c)
        std::copy(planes[c].begin(), planes[c].end(), (*whole)[c].begin() + static_cast<std::ptrdiff_t>(offset));
    if (reduce_preview)
      for (int r = 0; r < region.rows; ++r) {
        const int rj = static_cast<int>(static_cast<long>(region.first_row + r) * preview_face / size);
        for (int i = 0; i < size; ++i) {
          const int ri = static_cast<int>(static_cast<long>(i) * preview_face / size);
          const size_t at = (static_cast<size_t>(region.face) * preview_face + rj) * preview_face + ri;
          preview_sum[at] += cover[static_cast<size_t>(r) * size + i];
          ++preview_count[at];
        }
      }
  });
  add_timing(summary.timings, "coverage", milliseconds_since(start) - face_ms);
  summary.calibration = coverage.calibration();
  summary.bands = coverage.bands();

  CoverExport& exported = result.exported;
  if (options.faces) exported.timings.push_back({"write_faces", face_ms});
  if (streamed) {
    say("equirect");
    start = Clock::now();
    std::vector<cover::FacePointers> faces(static_cast<size_t>(channels));
    for (int c = 0; c < channels; ++c)
      for (int face = 0; face < 6; ++face)
        faces[static_cast<size_t>(c)][static_cast<size_t>(face)] =
            scratch_faces[static_cast<size_t>(c * 6 + face)]->map();
    files::ImageRowWriter map(outputs.reserve("cover_equirect.exr"), 4 * size, 2 * size, channels, exr,
                              outputs.final_path("cover_equirect.exr").string());
    cover::streamed_equirect(size, faces, 4 * size, 2 * size, [&](int, int rows, const std::vector<float>& pixels) {
      map.write_rows(rows, pixels.data());
    });
    map.close();
    scratch_faces.clear();
    exported.timings.push_back({"equirect_streamed", milliseconds_since(start)});
  }
  CoverImages images;
  images.face_size = size;
  start = Clock::now();
  if (whole) {
    say("equirect");
    const int width = 4 * size, height = 2 * size;
    CoverPlanes map;
    for (int c = 0; c < channels; ++c) map[c] = cover::equirect_from_faces(size, (*whole)[c], width, height);
    images.equirect = std::make_shared<core::ImageData>(
        core::ImageData{width, height, channels, interleaved_channels(map, 0, static_cast<size_t>(width) * height)});
    if (options.preview)
      images.preview = size > preview_face_limit
                           ? std::make_shared<core::ImageData>(preview_image(size, whole->cover))
                           : std::make_shared<core::ImageData>(core::ImageData{width, height, 1, std::move(map.cover)});
  } else if (reduce_preview) {
    say("preview");
    std::vector<float> reduced(preview_sum.size());
    for (size_t k = 0; k < reduced.size(); ++k) reduced[k] = static_cast<float>(preview_sum[k] / preview_count[k]);
    images.preview = std::make_shared<core::ImageData>(
        core::ImageData{4 * preview_face, 2 * preview_face, 1,
                        cover::equirect_from_faces(preview_face, reduced, 4 * preview_face, 2 * preview_face)});
  }
  if (images.equirect || images.preview) exported.timings.push_back({"equirect", milliseconds_since(start)});
  say("writing files");
  write_cover_images(outputs, images, options, exported);
  outputs.write("cover.json", json::write(cover_sidecar(summary, context, exported.timings, options)));
  return result;
}

}  // namespace nephele::io
