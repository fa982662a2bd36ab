#pragma once
// The density volume of a cloud model on the GPU (shaders/model/density.comp): an N^3 float
// 3D texture filled brick by brick, each brick blending only the primitives that reach it,
// and the edit of one primitive, which recomputes only the bricks of its old and new
// footprints. Needs a current OpenGL 4.5 context.
#include <cstdint>
#include <memory>
#include <vector>

#include "gpu/compute_program.hpp"
#include "gpu/storage_buffer.hpp"
#include "model/bricks.hpp"
#include "model/cloud_model.hpp"

namespace nephele::model {

struct PassStats {
  int bricks = 0;           // bricks of the volume
  int bricks_computed = 0;  // bricks the last pass wrote
  long pairs = 0;           // brick x primitive pairs it evaluated
  double ms = 0;            // its GPU time (gpu::PassTimer)
  // The share of bricks that the last pass computed.
  double occupancy() const { return bricks > 0 ? double(bricks_computed) / bricks : 0.0; }
};

class DensityVolume {
 public:
  // Bytes of device memory a volume of size^3 needs (the texture; the lists are small).
  static double device_bytes(int size);
  explicit DensityVolume(int size);
  ~DensityVolume();
  DensityVolume(const DensityVolume&) = delete;
  DensityVolume& operator=(const DensityVolume&) = delete;

  // Computes the whole volume (validates the model). cull = false lists every primitive in
  // every brick: the brute force that culling must reproduce exactly.
  void compute(const CloudModel& model, bool cull = true);
  // Replaces primitive `index` and recomputes the bricks of its old and new footprints only.
  // Throws ModelError for a bad index or primitive.
  void edit(int index, const Primitive& primitive);

  // Voxel (x, y, z) is values[(z * size + y) * size + x]; z is up.
  std::vector<float> read() const;
  int size() const { return grid_.size; }
  unsigned texture() const { return texture_; }
  const CloudModel& model() const { return model_; }
  const PassStats& stats() const { return stats_; }

 private:
  void run(const std::vector<int>& bricks);
  BrickGrid grid_;
  CloudModel model_;
  bool cull_ = true;
  std::vector<std::vector<std::uint32_t>> lists_;
  std::unique_ptr<gpu::ComputeProgram> program_;
  unsigned texture_ = 0;
  // The primitives, the bricks' jobs and their primitive lists (grown, never shrunk).
  gpu::StorageBuffer primitives_, jobs_, indices_;
  PassStats stats_;
};

// The same volume on the CPU by brute force (every primitive at every voxel), through the
// shared functions; for tests and small sizes.
std::vector<float> density_cpu(const CloudModel& model, int size);

}  // namespace nephele::model
