#include "io/noise_files.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "core/file_names.hpp"
#include "files/atomic_output.hpp"
#include "files/image_files.hpp"
#include "nephele/version.hpp"

namespace nephele::io {
namespace {

const char* format_name(FileFormat f, int png_bits) {
  switch (f) {
    case FileFormat::png: return png_bits == 16 ? "png16" : "png8";
    case FileFormat::exr: return "exr-float32";
    case FileFormat::raw: return "raw-float32-little-endian";
  }
  return "?";
}

json::Value fbm_json(const glsl::FbmParams& f, int width) {
  json::Value v;
  v.set("cells", json::Value::Array{json::Value(f.period.x), json::Value(f.period.y), json::Value(f.period.z)});
  v.set("cells_per_texel", static_cast<double>(f.period.x) / width);
  v.set("octaves", f.octaves);
  v.set("lacunarity", f.lacunarity);
  v.set("gain", f.gain);
  v.set("seed", static_cast<unsigned long>(f.seed));
  return v;
}

}  // namespace

FileFormat format_for(const std::filesystem::path& out) {
  const std::string ext = core::lowercase_extension(out);
  if (ext == ".png") return FileFormat::png;
  if (ext == ".exr") return FileFormat::exr;
  if (ext == ".raw") return FileFormat::raw;
  throw noise::SpecError("--out: '" + out.string() + "' has no known extension (allowed: .png, .exr, .raw)");
}

std::vector<float> slice_atlas(const noise::Volume& v) {
  std::vector<float> atlas(v.values.size());
  const size_t atlas_row = static_cast<size_t>(v.width) * v.depth * v.channels;
  const size_t slice_row = static_cast<size_t>(v.width) * v.channels;
  for (int z = 0; z < v.depth; ++z)
    for (int y = 0; y < v.height; ++y)
      std::memcpy(atlas.data() + y * atlas_row + z * slice_row,
                  v.values.data() + (static_cast<size_t>(z) * v.height + y) * slice_row, slice_row * sizeof(float));
  return atlas;
}

std::vector<ValueRange> channel_ranges(const noise::Volume& v) {
  std::vector<ValueRange> ranges(static_cast<size_t>(v.channels), ValueRange{1e30f, -1e30f});
  for (size_t i = 0; i < v.values.size(); ++i) {
    ValueRange& r = ranges[i % static_cast<size_t>(v.channels)];
    r.min = std::min(r.min, v.values[i]);
    r.max = std::max(r.max, v.values[i]);
  }
  return ranges;
}

std::vector<ValueRange> stretch_channels(noise::Volume& v) {
  const std::vector<ValueRange> ranges = channel_ranges(v);
  for (size_t i = 0; i < v.values.size(); ++i) {
    const ValueRange& r = ranges[i % static_cast<size_t>(v.channels)];
    const float span = r.max - r.min;
    v.values[i] = span > 0.0f ? std::clamp((v.values[i] - r.min) / span, 0.0f, 1.0f) : 0.0f;
  }
  return ranges;
}

json::Value sidecar(const noise::TextureSpec& spec, const noise::Volume& volume, FileFormat format, int png_bits,
                    const std::string& data_file, const std::string& preset, const json::Value& extra,
                    const std::vector<ValueRange>& stretched_from) {
  json::Value root;
  root.set("program", "nephele noise");
  root.set("version", version);
  root.set("file", data_file);
  root.set("format", format_name(format, png_bits));
  root.set("width", spec.width);
  root.set("height", spec.height);
  root.set("depth", spec.depth);
  std::string layout;
  for (size_t c = 0; c < spec.channels.size(); ++c) layout += noise::channel_letter(static_cast<int>(c));
  root.set("channels", layout);
  if (format == FileFormat::raw)
    root.set("layout",
             "float32 little-endian, channels interleaved, x fastest, then y, then z: value (x, y, z, c) at "
             "index ((z * height + y) * width + x) * channels + c");
  else
    root.set("layout", "slice atlas of " + std::to_string(spec.depth * spec.width) + " x " +
                           std::to_string(spec.height) +
                           " pixels: slice z at columns z * width .. (z + 1) * width - 1, "
                           "image row 0 is y = 0; texel (x, y, z) has its centre at (x + 0.5, y + 0.5, z + 0.5) / size "
                           "in texture coordinates, and the texture repeats exactly");
  if (format == FileFormat::png)
    root.set("quantisation", png_bits == 16 ? "round(65535 v), linear (no gamma, no sRGB)"
                                            : "round(255 v), linear (no gamma, no sRGB)");
  root.set("seed", static_cast<unsigned long>(spec.seed));
  root.set("preset", preset.empty() ? json::Value() : json::Value(preset));
  const std::vector<ValueRange> ranges = channel_ranges(volume);
  json::Value::Array channels;
  for (size_t c = 0; c < spec.channels.size(); ++c) {
    const glsl::NoiseChannel p = noise::channel_params(spec, static_cast<int>(c));
    json::Value ch;
    ch.set("channel", noise::channel_letter(static_cast<int>(c)));
    ch.set("type", type_name(spec.channels[c].type));
    ch.set("fbm", fbm_json(p.fbm, spec.width));
    if (p.type == glsl::NOISE_PERLIN_WORLEY) ch.set("worley_fbm", fbm_json(p.worley, spec.width));
    switch (p.type) {
      case glsl::NOISE_WORLEY: ch.set("value", "mean F1 / sqrt(3), F1 in cells (fBm: amplitude-weighted mean)"); break;
      case glsl::NOISE_INVERTED_WORLEY: ch.set("value", "1 - mean F1 / sqrt(3)"); break;
      case glsl::NOISE_PERLIN: ch.set("value", "1/2 + mean noise / (2 * 1.03636)"); break;
      default: ch.set("value", "remap(perlin, worley - 1, 1, 0, 1) = (perlin - worley + 1) / (2 - worley)"); break;
    }
    ch.set("bounds", json::Value::Array{json::Value(0.0), json::Value(1.0)});
    json::Value range;
    range.set("min", ranges[c].min);
    range.set("max", ranges[c].max);
    ch.set("range", range);
    if (!stretched_from.empty()) {
      // --stretch: stored = (value - min) / (max - min); value = min + stored (max - min).
      json::Value before;
      before.set("min", stretched_from[c].min);
      before.set("max", stretched_from[c].max);
      ch.set("stretched_from", before);
    }
    channels.push_back(ch);
  }
  root.set("channel_parameters", channels);
  if (!extra.is_null()) root.set("run", extra);
  return root;
}

std::filesystem::path write_noise_files(const std::filesystem::path& out, const noise::TextureSpec& spec,
                                        const noise::Volume& volume, int png_bits, const std::string& preset,
                                        const json::Value& extra, const std::vector<ValueRange>& stretched_from) {
  const FileFormat format = format_for(out);
  const std::filesystem::path directory = out.has_parent_path() ? out.parent_path() : std::filesystem::path(".");
  const std::string name = out.filename().string();
  const std::string sidecar_name = out.stem().string() + ".json";
  files::OutputSet outputs(directory, files::OutputSet::Scope::files);
  if (format == FileFormat::raw) {
    // float32 little-endian: the host's own layout on every platform nephele builds for.
    outputs.write(name, volume.values.data(), volume.values.size() * sizeof(float));
  } else {
    core::ImageData image{volume.width * volume.depth, volume.height, volume.channels, slice_atlas(volume)};
    files::ImageEncoding encoding = files::png_encoding(png_bits == 16 ? 16 : 8);
    if (format == FileFormat::exr) {
      static const char* const names[4][4] = {{"Y"}, {"R", "G"}, {"R", "G", "B"}, {"R", "G", "B", "A"}};
      encoding = files::exr_encoding({names[volume.channels - 1], names[volume.channels - 1] + volume.channels});
    }
    outputs.write(name, files::encode_image(image, encoding, name));
  }
  outputs.write(sidecar_name,
                json::write(sidecar(spec, volume, format, png_bits, name, preset, extra, stretched_from)));
  outputs.commit();
  return directory / sidecar_name;
}

}  // namespace nephele::io
