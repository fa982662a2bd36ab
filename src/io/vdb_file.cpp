// density.vdb through OpenVDB (the only file that includes it; docs/model.md, "Files"). Built
// without OpenVDB, vdb_available() is false and no .vdb is written.
#include "io/model_files.hpp"

#if NEPHELE_WITH_OPENVDB
#include <openvdb/io/File.h>
#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>

#include <sstream>
#endif

namespace nephele::io {

#if NEPHELE_WITH_OPENVDB

namespace {

// A FOG_VOLUME float grid of a width x height x depth volume (x fastest), zeros left as the
// background (sparse). Index (i, j, k) is the raw volume's voxel; OpenVDB puts a voxel's centre
// at its integer index, so world = s (index + 1/2): the volume spans [0, s size] on each axis.
openvdb::FloatGrid::Ptr fog_grid(const std::string& name, const std::vector<float>& values, int width, int height,
                                 int depth, double s) {
  openvdb::initialize();
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->setName(name);
  grid->setGridClass(openvdb::GRID_FOG_VOLUME);
  auto transform = openvdb::math::Transform::createLinearTransform(s);
  transform->postTranslate(openvdb::Vec3d(0.5 * s, 0.5 * s, 0.5 * s));
  grid->setTransform(transform);
  auto access = grid->getAccessor();
  for (int z = 0; z < depth; ++z)
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const float v = values[(size_t(z) * height + y) * width + x];
        if (v > 0.0f) access.setValue(openvdb::Coord(x, y, z), v);
      }
  return grid;
}

openvdb::FloatGrid::Ptr make_grid(const model::CloudModel& model, int size, const std::vector<float>& values) {
  auto grid = fog_grid("density", values, size, size, size, model.extent_m / size);
  grid->insertMeta("density_to_extinction_per_m", openvdb::DoubleMetadata(density_to_extinction_per_m));
  grid->insertMeta("creator", openvdb::StringMetadata("nephele model"));
  return grid;
}

std::string grids_bytes(const openvdb::GridCPtrVec& grids) {
  std::ostringstream out(std::ios_base::binary);
  openvdb::io::Stream(out).write(grids);
  return out.str();
}

}  // namespace

bool vdb_available() { return true; }

std::string vdb_bytes(const model::CloudModel& model, int size, const std::vector<float>& values) {
  return grids_bytes(openvdb::GridCPtrVec{make_grid(model, size, values)});
}

std::string vdb_grids_bytes(const std::vector<std::string>& names, const std::vector<std::vector<float>>& grids,
                            int width, int height, int depth, double voxel_size) {
  openvdb::GridCPtrVec out;
  for (std::size_t g = 0; g < grids.size(); ++g) {
    auto grid = fog_grid(names[g], grids[g], width, height, depth, voxel_size);
    grid->insertMeta("creator", openvdb::StringMetadata("nephele export"));
    out.push_back(grid);
  }
  return grids_bytes(out);
}

VdbContents read_vdb(const std::string& path) {
  openvdb::initialize();
  openvdb::io::File file(path);
  file.open();
  VdbContents c;
  for (auto name = file.beginName(); name != file.endName(); ++name) c.grids.push_back(name.gridName());
  auto base = file.readGrid("density");
  file.close();
  auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(base);
  if (!grid) throw std::runtime_error(path + ": 'density' is not a float grid");
  c.fog_volume = grid->getGridClass() == openvdb::GRID_FOG_VOLUME;
  c.background = grid->background();
  c.voxel_size = grid->voxelSize()[0];
  c.active = long(grid->activeVoxelCount());
  const auto origin = grid->indexToWorld(openvdb::Coord(0, 0, 0));
  c.origin = {origin[0], origin[1], origin[2]};
  for (auto v = grid->cbeginValueOn(); v; ++v) {
    const openvdb::Coord k = v.getCoord();
    c.values.push_back({k.x(), k.y(), k.z(), *v});
  }
  if (auto meta = grid->getMetadata<openvdb::DoubleMetadata>("density_to_extinction_per_m"))
    c.extinction_per_m = meta->value();
  return c;
}

#else

bool vdb_available() { return false; }
std::string vdb_bytes(const model::CloudModel&, int, const std::vector<float>&) { return {}; }
std::string vdb_grids_bytes(const std::vector<std::string>&, const std::vector<std::vector<float>>&, int, int, int,
                            double) {
  return {};
}
VdbContents read_vdb(const std::string& path) {
  throw std::runtime_error(path + ": nephele was built without OpenVDB");
}

#endif

}  // namespace nephele::io
