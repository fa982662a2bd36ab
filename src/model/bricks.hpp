#pragma once
// Bricks of the density volume and the primitives that reach them: the culling that makes the
// volume's cost follow the overlap of primitives with voxels rather than their product.
#include <cstdint>
#include <vector>

#include "model/cloud_model.hpp"

namespace nephele::model {

// Voxels per brick edge; shaders/model/density.comp's work group is this cube.
constexpr int brick_edge = 8;

struct BrickGrid {
  int size = 0;  // voxels per volume edge; voxel i has its centre at (i + 1/2) / size
  int per_axis() const { return (size + brick_edge - 1) / brick_edge; }
  int count() const { return per_axis() * per_axis() * per_axis(); }
};

// The bricks (index x + per_axis (y + per_axis z)) holding a voxel centre where the primitive's
// field may be non-zero: conservative, with a margin far above float rounding (bricks.cpp).
std::vector<int> footprint(const BrickGrid& grid, const Primitive& p);

// Per brick, the indices of the primitives that reach it, in the model's order.
std::vector<std::vector<std::uint32_t>> brick_lists(const BrickGrid& grid, const CloudModel& m);

}  // namespace nephele::model
