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
// The bins and points are laid out as every binned GSHHG file's (gshhg_bins.hpp).

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "io/gshhg_bins.hpp"

namespace nephele::io {
namespace {

using gshhg::Run;
using gshhg::SparseColumn;

// True for the 2-point zero-length stubs the binning leaves on bin W/S edges
// (16906 of the 43996 segments of binned_river_f.nc); they carry no geometry.
template <typename Column>
bool zero_length(const Column& dlon, const Column& dlat, const Run& run) {
  for (size_t p = run.start + 1; p < run.start + run.count; ++p)
    if (dlon.at(p) != dlon.at(run.start) || dlat.at(p) != dlat.at(run.start)) return false;
  return true;
}

}  // namespace

std::vector<RiverLine> read_gshhg_rivers(const std::string& path, double south_deg, double north_deg, double west_deg,
                                         double east_deg, int max_level) {
  gshhg::check_window("read_gshhg_rivers", south_deg, north_deg, west_deg, east_deg);
  const gshhg::NcFile file(path, "GSHHG river file");
  const gshhg::Grid grid = gshhg::read_grid(file);

  const gshhg::Var bin_first_seg = gshhg::find_var(file, "Id_of_first_segment_in_a_bin", {NC_INT});
  const gshhg::Var bin_n_seg = gshhg::find_var(file, "N_segments_in_a_bin", {NC_SHORT, NC_INT});
  const gshhg::Var seg_n_pts = gshhg::find_var(file, "N_points_for_a_segment", {NC_SHORT, NC_INT});
  const gshhg::Var seg_level = gshhg::find_var(file, "Hierarchial_level_of_a_segment", {NC_SHORT, NC_INT});
  const gshhg::Var seg_first_pt = gshhg::find_var(file, "Id_of_first_point_in_a_segment", {NC_INT});
  // Must be 16-bit signed storage: we reinterpret the bits as unsigned 0..65535.
  const gshhg::Var pt_dlon = gshhg::find_var(file, "Relative_longitude_from_SW_corner_of_bin", {NC_SHORT});
  const gshhg::Var pt_dlat = gshhg::find_var(file, "Relative_latitude_from_SW_corner_of_bin", {NC_SHORT});
  for (const gshhg::Var* v : {&bin_first_seg, &bin_n_seg}) gshhg::expect_length(*v, grid.n_bins);
  for (const gshhg::Var* v : {&seg_n_pts, &seg_level, &seg_first_pt}) gshhg::expect_length(*v, grid.n_segments);
  for (const gshhg::Var* v : {&pt_dlon, &pt_dlat}) gshhg::expect_length(*v, grid.n_points);

  std::vector<RiverLine> lines;
  if (max_level < 0) return lines;
  const double unit_deg = grid.bin_deg() / gshhg::bin_units;

  const std::vector<gshhg::PlacedBin> placed = gshhg::window_bins(grid, south_deg, north_deg, west_deg, east_deg);
  if (placed.empty()) return lines;

  // --- Bin index entries: one contiguous read covering the needed rows. ---
  const size_t first_bin = placed.front().index - placed.front().index % grid.nx;
  const Run bin_run{first_bin, placed.back().index / grid.nx * grid.nx + grid.nx - first_bin};
  const SparseColumn<int> first_seg(bin_first_seg, {bin_run});
  const SparseColumn<int> n_seg(bin_n_seg, {bin_run});

  std::vector<gshhg::PlacedBin> bins;
  std::vector<Run> seg_runs;
  for (const gshhg::PlacedBin& bin : placed) {
    const int first = first_seg.at(bin.index), count = n_seg.at(bin.index);
    if (count == 0) continue;
    if (first < 0 || count < 0 || static_cast<long>(first) + count > grid.n_segments)
      file.fail("bin " + std::to_string(bin.index) + " has an invalid segment range");
    bins.push_back(bin);
    seg_runs.push_back({static_cast<size_t>(first), static_cast<size_t>(count)});
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
      if (first < 0 || count < 0 || static_cast<long>(first) + count > grid.n_points)
        file.fail("segment " + std::to_string(s) + " has an invalid point range");
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
    const gshhg::PlacedBin& bin = bins[w.bin_pos];
    const double lat_sw = bin.lat_sw(grid), lon_sw = bin.lon_sw(grid);
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
