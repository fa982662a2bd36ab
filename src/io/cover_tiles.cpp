#include "io/cover_tiles.hpp"

#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "core/hash.hpp"
#include "core/input_file.hpp"
#include "files/atomic_output.hpp"
#include "io/cover_files.hpp"
#include "nephele/version.hpp"

#if !defined(__BYTE_ORDER__) || __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "tile parts store little-endian words as they are in memory"
#endif

namespace nephele::io {
namespace {

constexpr char magic[8] = {'N', 'E', 'P', 'H', 'T', 'I', 'L', '3'};
constexpr std::uint64_t max_header_bytes = 1u << 20;

// 64-bit integers as decimal text: JSON numbers (doubles) hold 53 bits.
std::string u64_text(std::uint64_t v) { return std::to_string(v); }

json::Value diagnosis_json(const cover::DiagnosisSums& s) {
  json::Value d;
  d.set("folded_units", u64_text(s.folded_units));
  d.set("beyond_units", u64_text(s.beyond_units));
  d.set("capped_texels", u64_text(s.capped_texels));
  d.set("off_sphere_texels", u64_text(s.off_sphere_texels));
  d.set("max_attempts", s.max_attempts);
  d.set("max_rate", s.max_rate);
  d.set("jacobian_min", s.jacobian_min);
  d.set("jacobian_max", s.jacobian_max);
  d.set("error_sum", s.error_sum);
  d.set("weight_sum", s.weight_sum);
  d.set("attempts_sum", s.attempts_sum);
  return d;
}

class HeaderReader {
 public:
  HeaderReader(const json::Value& root, std::string shown) : root_(root), shown_(std::move(shown)) {}
  const json::Value& at(const json::Value& object, const std::string& key) const {
    const json::Value* v = object.is_object() ? object.find(key) : nullptr;
    if (!v) fail(key, "is missing");
    return *v;
  }
  double number(const json::Value& object, const std::string& key) const {
    const json::Value& v = at(object, key);
    if (!v.is_number()) fail(key, "is not a number");
    return v.as_number();
  }
  int integer(const json::Value& object, const std::string& key, double low, double high) const {
    const double v = number(object, key);
    if (!(v >= low && v <= high) || v != static_cast<double>(static_cast<long long>(v)))
      fail(key, "is not a whole number from " + number_text(low) + " to " + number_text(high));
    return static_cast<int>(v);
  }
  std::uint64_t u64(const json::Value& object, const std::string& key) const {
    const json::Value& v = at(object, key);
    if (!v.is_string() || v.as_string().empty() || v.as_string().size() > 20 ||
        v.as_string().find_first_not_of("0123456789") != std::string::npos)
      fail(key, "is not a 64-bit unsigned integer in decimal text");
    return std::stoull(v.as_string());
  }
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    throw core::InputFileError(shown_ + ": '" + key + "' " + problem);
  }
  const json::Value& root() const { return root_; }

 private:
  static std::string number_text(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.0f", v);
    return buffer;
  }
  const json::Value& root_;
  std::string shown_;
};

}  // namespace

std::string tile_part_name(int index) {
  char name[32];
  std::snprintf(name, sizeof name, "tile_%06d.part", index);
  return name;
}

json::Value cover_identity(const std::vector<std::string>& arguments, const cover::CoverParameters& parameters) {
  json::Value identity;
  identity.set("program", "nephele");
  identity.set("version", version);
  json::Value::Array list;
  for (const std::string& a : arguments) list.emplace_back(a);
  identity.set("arguments", list);
  identity.set("parameters", cover_parameters_json(cover::resolved_curl(parameters)));
  return identity;
}

void write_tile_part(const std::filesystem::path& directory, const cover::TileDensity& tile, int tile_count,
                     const json::Value& identity) {
  const cover::CubeRegion& r = tile.region;
  const std::uint64_t bytes = tile.density.size() * sizeof(float);
  json::Value header;
  header.set("format", "nephele tile part 3");
  header.set("tile", tile.index);
  header.set("tiles", tile_count);
  header.set("face_size", r.face_size);
  header.set("face", r.face);
  header.set("first_row", r.first_row);
  header.set("rows", r.rows);
  header.set("owned_begin", r.owned_begin);
  header.set("owned_end", r.owned_end);
  header.set("density_min", static_cast<double>(tile.density_min));
  header.set("density_max", static_cast<double>(tile.density_max));
  header.set("diagnosis", diagnosis_json(tile.diagnosis));
  json::Value timings;
  for (const auto& t : tile.timings) {
    const json::Value* before = timings.find(t.pass);
    timings.set(t.pass, t.milliseconds + (before ? before->as_number() : 0.0));
  }
  header.set("timings_ms", timings);
  header.set("density_bytes", u64_text(bytes));
  header.set("density_hash", u64_text(core::block_hash(tile.density.data(), bytes)));
  if (tile.cloud_top.size() != tile.density.size() || tile.cover_contrast.size() != tile.density.size())
    throw std::invalid_argument("write_tile_part: a cloud top and a cover contrast per density");
  header.set("cloud_top_hash", u64_text(core::block_hash(tile.cloud_top.data(), bytes)));
  header.set("contrast_hash", u64_text(core::block_hash(tile.cover_contrast.data(), bytes)));
  header.set("cover", identity);
  const std::string text = json::write(header);
  const std::uint64_t length = text.size();
  files::replace_file(directory / tile_part_name(tile.index), {{magic, sizeof magic},
                                                               {&length, sizeof length},
                                                               {text.data(), text.size()},
                                                               {tile.density.data(), bytes},
                                                               {tile.cloud_top.data(), bytes},
                                                               {tile.cover_contrast.data(), bytes}});
}

TilePart read_tile_header(const std::filesystem::path& path) {
  const std::string shown = path.string();
  const std::uint64_t file_bytes = core::regular_file_size(shown);
  std::ifstream in(path, std::ios::binary);
  char head[16];
  if (!in.read(head, sizeof head) || std::memcmp(head, magic, sizeof magic) != 0)
    throw core::InputFileError(shown +
                               ": not a nephele tile part (no NEPHTIL3 magic; older parts (NEPHTIL1, NEPHTIL2) hold no "
                               "cloud tops or cover contrasts: generate them again)");
  std::uint64_t length = 0;
  std::memcpy(&length, head + 8, sizeof length);
  if (length == 0 || length > max_header_bytes || 16 + length > file_bytes)
    throw core::InputFileError(shown + ": header length " + std::to_string(length) + " outside 1 to " +
                               std::to_string(std::min<std::uint64_t>(max_header_bytes, file_bytes - 16)));
  std::string text(length, '\0');
  if (!in.read(text.data(), static_cast<std::streamsize>(length)))
    throw core::InputFileError(shown + ": the header is cut short");
  json::Value root;
  try {
    root = json::parse(text);
  } catch (const json::ParseError& e) {
    throw core::InputFileError(shown + ": header: " + e.what());
  }
  const HeaderReader h(root, shown);
  TilePart part;
  part.path = path;
  part.data_offset = 16 + length;
  const int face_size = h.integer(root, "face_size", 1, 65536);
  part.tile_count = h.integer(root, "tiles", 6, 6.0 * face_size);
  if (part.tile_count % 6 != 0) h.fail("tiles", "is not a multiple of 6");
  const cover::CubeTiling tiling{face_size, part.tile_count};
  part.tile.index = h.integer(root, "tile", 0, part.tile_count - 1);
  part.tile.region = tiling.tile(part.tile.index);
  // The place is recorded for readers; it must be the tiling's.
  const cover::CubeRegion& r = part.tile.region;
  const std::pair<const char*, int> place[] = {{"face", r.face},
                                               {"first_row", r.first_row},
                                               {"rows", r.rows},
                                               {"owned_begin", r.owned_begin},
                                               {"owned_end", r.owned_end}};
  for (const auto& [key, expected] : place)
    if (h.integer(root, key, 0, face_size) != expected)
      h.fail(key, "is not the place of tile " + std::to_string(part.tile.index) + " of " +
                      std::to_string(part.tile_count) + " (" + std::to_string(expected) + ")");
  part.tile.density_min = static_cast<float>(h.number(root, "density_min"));
  part.tile.density_max = static_cast<float>(h.number(root, "density_max"));
  const json::Value& d = h.at(root, "diagnosis");
  cover::DiagnosisSums& s = part.tile.diagnosis;
  s.folded_units = h.u64(d, "folded_units");
  s.beyond_units = h.u64(d, "beyond_units");
  s.capped_texels = h.u64(d, "capped_texels");
  s.off_sphere_texels = h.u64(d, "off_sphere_texels");
  s.max_attempts = h.number(d, "max_attempts");
  s.max_rate = h.number(d, "max_rate");
  s.jacobian_min = h.number(d, "jacobian_min");
  s.jacobian_max = h.number(d, "jacobian_max");
  s.error_sum = h.number(d, "error_sum");
  s.weight_sum = h.number(d, "weight_sum");
  s.attempts_sum = h.number(d, "attempts_sum");
  const json::Value& timings = h.at(root, "timings_ms");
  if (timings.is_object())
    for (const auto& [pass, ms] : timings.as_object())
      if (ms.is_number()) part.tile.timings.push_back({pass, ms.as_number()});
  const std::uint64_t bytes = h.u64(root, "density_bytes");
  if (bytes != static_cast<std::uint64_t>(r.owned_texels()) * sizeof(float))
    h.fail("density_bytes", "is not the tile's " + std::to_string(r.owned_texels()) + " float32 densities");
  if (file_bytes != part.data_offset + 3 * bytes)
    throw core::InputFileError(shown + ": " + std::to_string(file_bytes - part.data_offset) +
                               " bytes of densities, cloud tops and cover contrasts, not three times the header's " +
                               std::to_string(bytes));
  part.density_hash = h.u64(root, "density_hash");
  part.cloud_top_hash = h.u64(root, "cloud_top_hash");
  part.contrast_hash = h.u64(root, "contrast_hash");
  part.identity = h.at(root, "cover");
  return part;
}

std::optional<TilePart> find_tile_part(const std::filesystem::path& directory, int index, int tile_count,
                                       const json::Value& identity) {
  const std::filesystem::path path = directory / tile_part_name(index);
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return std::nullopt;
  TilePart part;
  try {
    part = read_tile_header(path);
  } catch (const core::InputFileError&) {
    return std::nullopt;  // cut short or damaged: made again
  }
  const json::Value* parameters = part.identity.find("parameters");
  if (part.tile_count != tile_count || part.tile.index != index || !parameters ||
      json::write(*parameters) != json::write(identity.at("parameters")))
    throw core::InputFileError(path.string() +
                               ": a part of another cover (other parameters or tile count); use another --out "
                               "directory, or remove the old parts");
  return part;
}

namespace {

// The part's block of a float per owned texel after `blocks_before` such blocks, checked
// against `hash` (the header's `hash_key`).
std::vector<float> read_tile_block(const TilePart& part, int blocks_before, std::uint64_t hash, const char* what,
                                   const char* hash_key) {
  const std::string shown = part.path.string();
  const std::size_t count = static_cast<std::size_t>(part.tile.region.owned_texels());
  std::vector<float> values(count);
  std::ifstream in(part.path, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(part.data_offset + blocks_before * count * sizeof(float)));
  if (!in.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(count * sizeof(float))))
    throw core::InputFileError(shown + ": the " + what + " are cut short");
  if (core::block_hash(values.data(), count * sizeof(float)) != hash)
    throw core::InputFileError(shown + ": the " + what + " do not match the header's " + hash_key +
                               " (a damaged file)");
  return values;
}

}  // namespace

std::vector<float> read_tile_densities(const TilePart& part) {
  return read_tile_block(part, 0, part.density_hash, "densities", "density_hash");
}

std::vector<float> read_tile_cloud_tops(const TilePart& part) {
  return read_tile_block(part, 1, part.cloud_top_hash, "cloud tops", "cloud_top_hash");
}

std::vector<float> read_tile_cover_contrasts(const TilePart& part) {
  return read_tile_block(part, 2, part.contrast_hash, "cover contrasts", "contrast_hash");
}

}  // namespace nephele::io
