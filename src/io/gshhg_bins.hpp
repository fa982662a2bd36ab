#pragma once
// What GSHHG's binned netCDF files (GMT's shorelines, rivers and borders) have in common: the
// global grid of square bins, the variables read with their checks, and the bins a latitude and
// longitude window needs (river_files.hpp, coastline_files.hpp).
//
// Bin b covers row = b / nx, col = b % nx; row 0 is the northernmost band, so the SW corner is
// (90 - (row+1)*size, col*size) with col 0 starting at 0 E. Point offsets are UNSIGNED 16-bit
// values stored in signed shorts; 0..65535 spans the whole bin (65535 lies on the N or E edge).
#include <netcdf.h>

#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

namespace nephele::io::gshhg {

// The largest point offset: the far (N or E) edge of a bin.
inline constexpr double bin_units = 65535.0;

// An open netCDF file whose errors name it and what it holds ("GSHHG river file").
class NcFile {
 public:
  NcFile(const std::string& path, std::string kind);
  ~NcFile();
  NcFile(const NcFile&) = delete;
  NcFile& operator=(const NcFile&) = delete;
  int id() const { return id_; }
  const std::string& path() const { return path_; }
  [[noreturn]] void fail(const std::string& what) const;
  void check(int status, const std::string& what) const;

 private:
  std::string path_, kind_;
  int id_ = -1;
};

// A 1-D variable, checked for existence, rank and element type.
struct Var {
  const NcFile* file = nullptr;
  std::string name;
  int id = -1;
  std::size_t length = 0;
};
Var find_var(const NcFile& f, const char* name, std::initializer_list<nc_type> allowed);
void expect_length(const Var& v, long expected);

// The grid's scalars, checked to be a global grid of square bins.
struct Grid {
  int bin_minutes = 0, nx = 0, ny = 0, n_bins = 0, n_segments = 0, n_points = 0;
  double bin_deg() const { return bin_minutes / 60.0; }
};
Grid read_grid(const NcFile& f);

// Checks a window (degrees: finite, south <= north, west <= east, at most 360 wide; `who` names
// the caller in the message of std::invalid_argument) and clamps its latitudes to [-90, 90].
void check_window(const char* who, double& south_deg, double& north_deg, double west_deg, double east_deg);

// A bin the window needs, with the longitude shift (a multiple of 360) that puts it into the
// window's frame.
struct PlacedBin {
  std::size_t index = 0;
  double lon_shift = 0.0;
  double lat_sw(const Grid& g) const { return 90.0 - double(index / g.nx + 1) * g.bin_deg(); }
  double lon_sw(const Grid& g) const { return double(index % g.nx) * g.bin_deg() + lon_shift; }
};
// Every bin whose area overlaps the window by a positive area (or, for a window of no width,
// touches it), rows north to south, in each the file's columns from 0 E. A bin that only touches a window's edge
// adds nothing: what crosses that edge has its edge point in the inside bin too.
std::vector<PlacedBin> window_bins(const Grid& g, double south_deg, double north_deg, double west_deg, double east_deg);

struct Run {
  std::size_t start = 0;
  std::size_t count = 0;
};

// Values of one variable at a sparse set of index runs. Runs are merged when they overlap or lie
// closer than `max_gap` elements (the arrays are deflated in chunks of 33k-65k elements, so HDF5
// decompresses a whole chunk anyway: copying a few thousand unwanted values is cheaper than
// another call), so that each block costs one read.
template <typename T>
class SparseColumn {
 public:
  SparseColumn(const Var& var, std::vector<Run> runs, std::size_t max_gap = 4096);
  // Precondition: index lies inside one of the runs given to the constructor.
  T at(std::size_t index) const {
    const auto it = std::upper_bound(starts_.begin(), starts_.end(), index);
    const std::size_t k = static_cast<std::size_t>(it - starts_.begin()) - 1;
    return blocks_[k][index - starts_[k]];
  }

 private:
  std::vector<std::size_t> starts_;
  std::vector<std::vector<T>> blocks_;
};
extern template class SparseColumn<int>;
extern template class SparseColumn<short>;

}  // namespace nephele::io::gshhg
