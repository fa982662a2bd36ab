#include "cover/cube_tiles.hpp"

#include <stdexcept>

#include "gpu/compute_program.hpp"

namespace nephele::cover {

CubeRegion CubeRegion::whole(int face_size) {
  CubeRegion region;
  region.face_size = face_size;
  region.rows = face_size;
  region.owned_end = face_size;
  return region;
}

CubeRegion CubeTiling::tile(int index) const {
  if (index < 0 || index >= count) throw std::out_of_range("CubeTiling::tile: index outside the tiling");
  const int strips = strips_per_face();
  const int strip = index % strips;
  // Strip s holds rows [s N / S, (s + 1) N / S): sizes differ by at most one row.
  const int begin = static_cast<int>(std::int64_t(strip) * face_size / strips);
  const int end = static_cast<int>(std::int64_t(strip + 1) * face_size / strips);
  const int halo_before = begin > 0 ? 1 : 0, halo_after = end < face_size ? 1 : 0;
  CubeRegion region;
  region.face_size = face_size;
  region.face = index / strips;
  region.layers = 1;
  region.first_row = begin - halo_before;
  region.rows = end - begin + halo_before + halo_after;
  region.owned_begin = halo_before;
  region.owned_end = halo_before + (end - begin);
  return region;
}

std::string tile_count_problem(int face_size, std::int64_t count) {
  if (count < 6 || count % 6 != 0) return "is not a multiple of 6 (each face is cut into the same number of strips)";
  if (count > max_tile_count(face_size))
    return "cuts a face of " + std::to_string(face_size) + " rows into strips of less than a row";
  return "";
}

void set_region(const gpu::ComputeProgram& program, const CubeRegion& region) {
  program.set("u_face_size", region.face_size);
  program.set("u_tile_origin", glm::ivec2(region.first_row, region.face));
  program.set("u_tile_rows", glm::ivec2(region.owned_begin, region.owned_end));
}

}  // namespace nephele::cover
