#include "io/gshhg_bins.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace nephele::io::gshhg {
namespace {

int read_scalar(const NcFile& f, const char* name) {
  const Var v = find_var(f, name, {NC_INT, NC_SHORT});
  if (v.length < 1) f.fail(std::string("scalar ") + name + " is empty");
  const std::size_t index = 0;
  int value = 0;
  f.check(nc_get_var1_int(f.id(), v.id, &index, &value), std::string("reading ") + name);
  return value;
}

// Typed nc_get_vara wrappers; netCDF converts any integer storage type.
int get_vara(int nc, int var, std::size_t start, std::size_t count, int* out) {
  return nc_get_vara_int(nc, var, &start, &count, out);
}
int get_vara(int nc, int var, std::size_t start, std::size_t count, short* out) {
  return nc_get_vara_short(nc, var, &start, &count, out);
}

// Does bin interval [a, b] intersect window interval [lo, hi]? For a window of positive width the
// overlap must have positive length; a zero-width window (one meridian or parallel, or a point)
// uses closed intervals so that it is not lost.
bool intersects(double a, double b, double lo, double hi) {
  if (hi > lo) return std::min(b, hi) - std::max(a, lo) > 0.0;
  return a <= lo && lo <= b;
}

}  // namespace

NcFile::NcFile(const std::string& path, std::string kind) : path_(path), kind_(std::move(kind)) {
  check(nc_open(path.c_str(), NC_NOWRITE, &id_), "cannot open");
}
NcFile::~NcFile() { nc_close(id_); }

void NcFile::fail(const std::string& what) const { throw std::runtime_error(kind_ + " '" + path_ + "': " + what); }

void NcFile::check(int status, const std::string& what) const {
  if (status != NC_NOERR) fail(what + ": " + nc_strerror(status));
}

Var find_var(const NcFile& f, const char* name, std::initializer_list<nc_type> allowed) {
  Var v{&f, name, -1, 0};
  f.check(nc_inq_varid(f.id(), name, &v.id), std::string("missing variable ") + name);
  int ndims = 0;
  nc_type type = NC_NAT;
  f.check(nc_inq_varndims(f.id(), v.id, &ndims), name);
  if (ndims != 1) f.fail(std::string("variable ") + name + " is not one-dimensional");
  int dim = -1;
  f.check(nc_inq_vardimid(f.id(), v.id, &dim), name);
  f.check(nc_inq_dimlen(f.id(), dim, &v.length), name);
  f.check(nc_inq_vartype(f.id(), v.id, &type), name);
  if (std::find(allowed.begin(), allowed.end(), type) == allowed.end())
    f.fail(std::string("variable ") + name + " has an unexpected type");
  return v;
}

void expect_length(const Var& v, long expected) {
  if (expected < 0 || v.length != static_cast<std::size_t>(expected))
    v.file->fail("variable " + v.name + " has length " + std::to_string(v.length) + ", expected " +
                 std::to_string(expected));
}

Grid read_grid(const NcFile& f) {
  Grid g;
  g.bin_minutes = read_scalar(f, "Bin_size_in_minutes");
  g.nx = read_scalar(f, "N_bins_in_360_longitude_range");
  g.ny = read_scalar(f, "N_bins_in_180_degree_latitude_range");
  g.n_bins = read_scalar(f, "N_bins_in_file");
  g.n_segments = read_scalar(f, "N_segments_in_file");
  g.n_points = read_scalar(f, "N_points_in_file");
  if (g.bin_minutes <= 0 || g.nx <= 0 || g.ny <= 0 || static_cast<long>(g.nx) * g.bin_minutes != 360L * 60 ||
      static_cast<long>(g.ny) * g.bin_minutes != 180L * 60 || static_cast<long>(g.nx) * g.ny != g.n_bins)
    f.fail("bin grid scalars are not a global grid (bin " + std::to_string(g.bin_minutes) + "', " +
           std::to_string(g.nx) + " x " + std::to_string(g.ny) + ", " + std::to_string(g.n_bins) + " bins)");
  return g;
}

void check_window(const char* who, double& south_deg, double& north_deg, double west_deg, double east_deg) {
  for (double v : {south_deg, north_deg, west_deg, east_deg})
    if (!std::isfinite(v)) throw std::invalid_argument(std::string(who) + ": non-finite window bound");
  if (south_deg > north_deg) throw std::invalid_argument(std::string(who) + ": south > north");
  if (west_deg > east_deg) throw std::invalid_argument(std::string(who) + ": west > east");
  if (east_deg - west_deg > 360.0) throw std::invalid_argument(std::string(who) + ": window wider than 360 degrees");
  south_deg = std::max(south_deg, -90.0);
  north_deg = std::min(north_deg, 90.0);
}

std::vector<PlacedBin> window_bins(const Grid& g, double south_deg, double north_deg, double west_deg,
                                   double east_deg) {
  const double bin_deg = g.bin_deg();
  // Columns: a bin may overlap the window at two 360-degree shifts (only if the window is 360
  // wide, one of them merely touching); the larger overlap places it inside the window.
  std::vector<std::pair<int, double>> cols;
  for (int c = 0; c < g.nx; ++c) {
    const double w = c * bin_deg;
    const double k0 = std::ceil((west_deg - bin_deg - w) / 360.0);  // the smallest shift reaching west
    double best_shift = 0.0, best_overlap = -1.0;
    for (double k : {k0, k0 + 1.0}) {
      const double west_edge = w + 360.0 * k;
      if (!intersects(west_edge, west_edge + bin_deg, west_deg, east_deg)) continue;
      const double overlap = std::min(west_edge + bin_deg, east_deg) - std::max(west_edge, west_deg);
      if (overlap > best_overlap) best_overlap = overlap, best_shift = 360.0 * k;
    }
    if (best_overlap >= 0.0) cols.emplace_back(c, best_shift);
  }
  std::vector<PlacedBin> bins;
  for (int r = 0; r < g.ny; ++r) {
    const double lat_sw = 90.0 - (r + 1) * bin_deg;
    if (!intersects(lat_sw, lat_sw + bin_deg, south_deg, north_deg)) continue;
    for (const auto& [c, shift] : cols) bins.push_back({static_cast<std::size_t>(r) * g.nx + c, shift});
  }
  return bins;
}

template <typename T>
SparseColumn<T>::SparseColumn(const Var& var, std::vector<Run> runs, std::size_t max_gap) {
  std::sort(runs.begin(), runs.end(), [](const Run& a, const Run& b) { return a.start < b.start; });
  std::size_t i = 0;
  while (i < runs.size()) {
    if (runs[i].count == 0) {
      ++i;
      continue;
    }
    const std::size_t begin = runs[i].start;
    std::size_t end = begin + runs[i].count;
    for (++i; i < runs.size() && runs[i].start <= end + max_gap; ++i)
      end = std::max(end, runs[i].start + runs[i].count);
    if (end > var.length) var.file->fail("index past the end of " + var.name + " (file inconsistent)");
    starts_.push_back(begin);
    blocks_.emplace_back(end - begin);
    var.file->check(get_vara(var.file->id(), var.id, begin, end - begin, blocks_.back().data()), "reading " + var.name);
  }
}

template class SparseColumn<int>;
template class SparseColumn<short>;

}  // namespace nephele::io::gshhg
