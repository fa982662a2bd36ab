#include "io/river_files.hpp"

// Layout of binned_river_*.nc (GSHHG 2.3.7), as verified on the whole file
// against Debian's binned_river_f.nc and consistent with GMT's gmt_shore.c:
//
//   scalars   Bin_size_in_minutes (60 for "f"), N_bins_in_360_longitude_range
//             (nx), N_bins_in_180_degree_latitude_range (ny), N_bins_in_file
//             (nx*ny), N_segments_in_file, N_points_in_file
//   per bin   Id_of_first_segment_in_a_bin (int), N_segments_in_a_bin (short)
//   per seg   N_points_for_a_segment (short), Hierarchial_level_of_a_segment
//             (short, WDB II class 0..10; sic, "Hierarchial"),
//             Id_of_first_point_in_a_segment (int)
//   per point Relative_longitude/latitude_from_SW_corner_of_bin (short)
//
// Bin b covers row = b / nx, col = b % nx; row 0 is the northernmost band, so
// the SW corner is (90 - (row+1)*size, col*size) with col 0 starting at 0 E.
// Point offsets are UNSIGNED 16-bit values stored in signed shorts; 0..65535
// spans the full bin, i.e. one unit = bin size / 65535 (65535 lies exactly on
// the N/E edge, where the continuation in the next bin starts at 0).

#include <netcdf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace nephele::io {
namespace {

// Gap (in array elements) up to which two wanted index runs are read with one
// nc_get_vara call.  The arrays are deflated in chunks of ~33k-65k elements, so
// HDF5 decompresses the whole chunk anyway; copying a few thousand unwanted
// values is cheaper than another call.
constexpr size_t kMaxGap = 4096;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw std::runtime_error("GSHHG river file '" + path + "': " + what);
}

void check(int status, const std::string& path, const std::string& what) {
  if (status != NC_NOERR) fail(path, what + ": " + nc_strerror(status));
}

// Closes the file on every exit path, including exceptions.
class NcFile {
 public:
  explicit NcFile(const std::string& path) : path_(path) {
    check(nc_open(path.c_str(), NC_NOWRITE, &id_), path, "cannot open");
  }
  ~NcFile() { nc_close(id_); }
  NcFile(const NcFile&) = delete;
  NcFile& operator=(const NcFile&) = delete;
  int id() const { return id_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int id_ = -1;
};

// A 1-D variable, checked for existence, rank and element type.
struct Var {
  const NcFile* file = nullptr;
  std::string name;
  int id = -1;
  size_t length = 0;
};

Var find_var(const NcFile& f, const char* name, std::initializer_list<nc_type> allowed) {
  Var v{&f, name, -1, 0};
  check(nc_inq_varid(f.id(), name, &v.id), f.path(), std::string("missing variable ") + name);
  int ndims = 0;
  nc_type type = NC_NAT;
  check(nc_inq_varndims(f.id(), v.id, &ndims), f.path(), name);
  if (ndims != 1) fail(f.path(), std::string("variable ") + name + " is not one-dimensional");
  int dim = -1;
  check(nc_inq_vardimid(f.id(), v.id, &dim), f.path(), name);
  check(nc_inq_dimlen(f.id(), dim, &v.length), f.path(), name);
  check(nc_inq_vartype(f.id(), v.id, &type), f.path(), name);
  if (std::find(allowed.begin(), allowed.end(), type) == allowed.end())
    fail(f.path(), std::string("variable ") + name + " has an unexpected type");
  return v;
}

void expect_length(const Var& v, long expected) {
  if (expected < 0 || v.length != static_cast<size_t>(expected))
    fail(v.file->path(),
         "variable " + v.name + " has length " + std::to_string(v.length) + ", expected " + std::to_string(expected));
}

int read_scalar(const NcFile& f, const char* name) {
  const Var v = find_var(f, name, {NC_INT, NC_SHORT});
  if (v.length < 1) fail(f.path(), std::string("scalar ") + name + " is empty");
  const size_t index = 0;
  int value = 0;
  check(nc_get_var1_int(f.id(), v.id, &index, &value), f.path(), std::string("reading ") + name);
  return value;
}

// Typed nc_get_vara wrappers; netCDF converts any integer storage type.
int get_vara(int nc, int var, size_t start, size_t count, int* out) {
  return nc_get_vara_int(nc, var, &start, &count, out);
}
int get_vara(int nc, int var, size_t start, size_t count, short* out) {
  return nc_get_vara_short(nc, var, &start, &count, out);
}

struct Run {
  size_t start = 0;
  size_t count = 0;
};

// Values of one variable at a sparse set of index runs.  Runs are merged when
// they overlap or are close (kMaxGap) so that each block costs one read.
template <typename T>
class SparseColumn {
 public:
  SparseColumn(const Var& var, std::vector<Run> runs) {
    std::sort(runs.begin(), runs.end(), [](const Run& a, const Run& b) { return a.start < b.start; });
    size_t i = 0;
    while (i < runs.size()) {
      if (runs[i].count == 0) {
        ++i;
        continue;
      }
      const size_t begin = runs[i].start;
      size_t end = begin + runs[i].count;
      for (++i; i < runs.size() && runs[i].start <= end + kMaxGap; ++i)
        end = std::max(end, runs[i].start + runs[i].count);
      if (end > var.length) fail(var.file->path(), "index past the end of " + var.name + " (file inconsistent)");
      starts_.push_back(begin);
      blocks_.emplace_back(end - begin);
      check(get_vara(var.file->id(), var.id, begin, end - begin, blocks_.back().data()), var.file->path(),
            "reading " + var.name);
    }
  }

  // Precondition: index lies inside one of the runs given to the constructor.
  T at(size_t index) const {
    const auto it = std::upper_bound(starts_.begin(), starts_.end(), index);
    const size_t k = static_cast<size_t>(it - starts_.begin()) - 1;
    return blocks_[k][index - starts_[k]];
  }

 private:
  std::vector<size_t> starts_;
  std::vector<std::vector<T>> blocks_;
};

// Does bin interval [a, b] intersect window interval [lo, hi]?  For a window
// of positive width the overlap must have positive length: a bin that only
// touches the window edge adds nothing, because a line crossing that edge has
// its edge point stored in the inside bin too.  A zero-width window (a single
// meridian/parallel or point) uses closed intervals so it is not lost.
bool intersects(double a, double b, double lo, double hi) {
  if (hi > lo) return std::min(b, hi) - std::max(a, lo) > 0.0;
  return a <= lo && lo <= b;
}

// True for the 2-point zero-length stubs the binning leaves on bin W/S edges
// (16906 of the 43996 segments of binned_river_f.nc); they carry no geometry.
template <typename Column>
bool zero_length(const Column& dlon, const Column& dlat, const Run& run) {
  for (size_t p = run.start + 1; p < run.start + run.count; ++p)
    if (dlon.at(p) != dlon.at(run.start) || dlat.at(p) != dlat.at(run.start)) return false;
  return true;
}

// A bin chosen for output, with the longitude shift (multiple of 360) that
// puts it into the caller's window.
struct SelectedBin {
  size_t index = 0;
  double lon_shift = 0.0;
};

}  // namespace

std::vector<RiverLine> read_gshhg_rivers(const std::string& path, double south_deg, double north_deg, double west_deg,
                                         double east_deg, int max_level) {
  for (double v : {south_deg, north_deg, west_deg, east_deg})
    if (!std::isfinite(v)) throw std::invalid_argument("read_gshhg_rivers: non-finite window bound");
  if (south_deg > north_deg) throw std::invalid_argument("read_gshhg_rivers: south > north");
  if (west_deg > east_deg) throw std::invalid_argument("read_gshhg_rivers: west > east");
  if (east_deg - west_deg > 360.0) throw std::invalid_argument("read_gshhg_rivers: window wider than 360 degrees");
  south_deg = std::max(south_deg, -90.0);
  north_deg = std::min(north_deg, 90.0);

  const NcFile file(path);

  // --- Grid description; check it is the global grid we understand. ---
  const int bin_minutes = read_scalar(file, "Bin_size_in_minutes");
  const int nx = read_scalar(file, "N_bins_in_360_longitude_range");
  const int ny = read_scalar(file, "N_bins_in_180_degree_latitude_range");
  const int n_bins = read_scalar(file, "N_bins_in_file");
  const int n_segments = read_scalar(file, "N_segments_in_file");
  const int n_points = read_scalar(file, "N_points_in_file");
  if (bin_minutes <= 0 || nx <= 0 || ny <= 0 || static_cast<long>(nx) * bin_minutes != 360L * 60 ||
      static_cast<long>(ny) * bin_minutes != 180L * 60 || static_cast<long>(nx) * ny != n_bins)
    fail(path, "bin grid scalars are not a global grid (bin " + std::to_string(bin_minutes) + "', " +
                   std::to_string(nx) + " x " + std::to_string(ny) + ", " + std::to_string(n_bins) + " bins)");

  const Var bin_first_seg = find_var(file, "Id_of_first_segment_in_a_bin", {NC_INT});
  const Var bin_n_seg = find_var(file, "N_segments_in_a_bin", {NC_SHORT, NC_INT});
  const Var seg_n_pts = find_var(file, "N_points_for_a_segment", {NC_SHORT, NC_INT});
  const Var seg_level = find_var(file, "Hierarchial_level_of_a_segment", {NC_SHORT, NC_INT});
  const Var seg_first_pt = find_var(file, "Id_of_first_point_in_a_segment", {NC_INT});
  // Must be 16-bit signed storage: we reinterpret the bits as unsigned 0..65535.
  const Var pt_dlon = find_var(file, "Relative_longitude_from_SW_corner_of_bin", {NC_SHORT});
  const Var pt_dlat = find_var(file, "Relative_latitude_from_SW_corner_of_bin", {NC_SHORT});
  for (const Var* v : {&bin_first_seg, &bin_n_seg}) expect_length(*v, n_bins);
  for (const Var* v : {&seg_n_pts, &seg_level, &seg_first_pt}) expect_length(*v, n_segments);
  for (const Var* v : {&pt_dlon, &pt_dlat}) expect_length(*v, n_points);

  std::vector<RiverLine> lines;
  if (max_level < 0) return lines;

  const double bin_deg = bin_minutes / 60.0;
  const double unit_deg = bin_deg / 65535.0;  // 65535 = the far (N or E) bin edge

  // --- Rows: row r spans latitudes [90-(r+1)*bin, 90-r*bin]. ---
  int row_lo = ny, row_hi = -1;
  for (int r = 0; r < ny; ++r) {
    const double lat_sw = 90.0 - (r + 1) * bin_deg;
    if (intersects(lat_sw, lat_sw + bin_deg, south_deg, north_deg)) {
      row_lo = std::min(row_lo, r);
      row_hi = std::max(row_hi, r);
    }
  }
  if (row_hi < 0) return lines;

  // --- Columns: a bin may overlap the window at two 360-degree shifts (only
  // if the window is 360 wide, one of them merely touching); take the shift
  // with the larger overlap so such a bin is reported inside the window. ---
  std::vector<std::pair<int, double>> cols;  // (column, longitude shift)
  for (int c = 0; c < nx; ++c) {
    const double w = c * bin_deg;
    const double k0 = std::ceil((west_deg - bin_deg - w) / 360.0);  // smallest shift reaching west
    double best_shift = 0.0, best_overlap = -1.0;
    for (double k : {k0, k0 + 1.0}) {
      const double west_edge = w + 360.0 * k;
      if (!intersects(west_edge, west_edge + bin_deg, west_deg, east_deg)) continue;
      const double overlap = std::min(west_edge + bin_deg, east_deg) - std::max(west_edge, west_deg);
      if (overlap > best_overlap) best_overlap = overlap, best_shift = 360.0 * k;
    }
    if (best_overlap >= 0.0) cols.emplace_back(c, best_shift);
  }
  if (cols.empty()) return lines;

  // --- Bin index entries: one contiguous read covering the needed rows. ---
  const Run bin_run{static_cast<size_t>(row_lo) * nx, static_cast<size_t>(row_hi - row_lo + 1) * nx};
  const SparseColumn<int> first_seg(bin_first_seg, {bin_run});
  const SparseColumn<int> n_seg(bin_n_seg, {bin_run});

  std::vector<SelectedBin> bins;
  std::vector<Run> seg_runs;
  for (int r = row_lo; r <= row_hi; ++r) {
    for (const auto& [c, shift] : cols) {
      const size_t b = static_cast<size_t>(r) * nx + c;
      const int first = first_seg.at(b), count = n_seg.at(b);
      if (count == 0) continue;
      if (first < 0 || count < 0 || static_cast<long>(first) + count > n_segments)
        fail(path, "bin " + std::to_string(b) + " has an invalid segment range");
      bins.push_back({b, shift});
      seg_runs.push_back({static_cast<size_t>(first), static_cast<size_t>(count)});
    }
  }
  if (bins.empty()) return lines;

  // --- Segment records of the selected bins; keep the wanted levels. ---
  const SparseColumn<int> n_pts(seg_n_pts, seg_runs);
  const SparseColumn<int> level(seg_level, seg_runs);
  const SparseColumn<int> first_pt(seg_first_pt, seg_runs);

  struct Wanted {
    size_t bin_pos;  // index into `bins`
    int level;
    Run points;
  };
  std::vector<Wanted> wanted;
  std::vector<Run> pt_runs;
  for (size_t i = 0; i < bins.size(); ++i) {
    for (size_t s = seg_runs[i].start; s < seg_runs[i].start + seg_runs[i].count; ++s) {
      const int lev = level.at(s);
      if (lev < 0 || lev > max_level) continue;
      const int first = first_pt.at(s), count = n_pts.at(s);
      if (first < 0 || count < 0 || static_cast<long>(first) + count > n_points)
        fail(path, "segment " + std::to_string(s) + " has an invalid point range");
      const Run run{static_cast<size_t>(first), static_cast<size_t>(count)};
      wanted.push_back({i, lev, run});
      pt_runs.push_back(run);
    }
  }

  // --- Points of the kept segments, converted to degrees. ---
  const SparseColumn<short> dlon(pt_dlon, pt_runs);
  const SparseColumn<short> dlat(pt_dlat, pt_runs);
  lines.reserve(wanted.size());
  for (const Wanted& w : wanted) {
    if (zero_length(dlon, dlat, w.points)) continue;
    const SelectedBin& bin = bins[w.bin_pos];
    const size_t row = bin.index / nx, col = bin.index % nx;
    const double lat_sw = 90.0 - (row + 1) * bin_deg;
    const double lon_sw = col * bin_deg + bin.lon_shift;
    RiverLine line;
    line.level = w.level;
    line.points.reserve(w.points.count);
    for (size_t p = w.points.start; p < w.points.start + w.points.count; ++p) {
      // The shorts hold unsigned offsets; go through uint16_t to undo the sign.
      const auto u = static_cast<std::uint16_t>(dlon.at(p));
      const auto v = static_cast<std::uint16_t>(dlat.at(p));
      line.points.emplace_back(lat_sw + v * unit_deg, lon_sw + u * unit_deg);
    }
    lines.push_back(std::move(line));
  }
  return lines;
}

}  // namespace nephele::io
