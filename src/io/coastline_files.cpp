#include "io/coastline_files.hpp"

// The shoreline file's layout beyond the grid that every binned GSHHG file shares
// (gshhg_bins.hpp), as GMT's gmt_shore.c reads it:
//   per bin   Id_of_first_segment_in_a_bin (int), N_segments_in_a_bin (short),
//             Embedded_node_levels_in_a_bin (short): the levels of the bin's corners, three bits
//             each, counter-clockwise from the south-west corner in bits 9-11 (south-east 6-8,
//             north-east 3-5, north-west 0-2)
//   per seg   Embedded_npts_levels_exit_entry_for_a_segment (int): points (bits 9 and up), level
//             (6-8), the side where it enters (3-5) and leaves (0-2) the bin: 0 south, 1 east,
//             2 north, 3 west, 4 none (a polygon closed inside the bin);
//             Id_of_first_point_in_a_segment (int)
//   per point Relative_longitude/latitude_from_SW_corner_of_bin (short)
// A segment is a piece of one polygon's outline inside one bin; the pieces of an outline that
// leaves a bin end on its edges. Antarctica has two outlines: its ice front (level 1) and its
// grounding line (level 6, within the ice shelves). The corners' levels go with the ice front:
// leaving out level 6, the corners agree with the segments' ends on every bin of the file (the
// water flips at each end along an edge).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/parallel_rows.hpp"
#include "io/gshhg_bins.hpp"

namespace nephele::io {
namespace {

using gshhg::Run;
using gshhg::SparseColumn;

constexpr int side_west = 3;
constexpr int level_grounding_line = 6;  // Antarctica's grounding line

struct Segment {
  int entry = 4, exit = 4;  // the sides where it enters and leaves its bin
  Run points;
};

struct Bin {
  gshhg::PlacedBin place;
  bool south_west_wet = true;  // the level of the south-west corner is even
  std::vector<Segment> segments;
};

// One bin's water along the sub-rows of the window that cross it, added to `water` (per pixel,
// the water's length in pixel widths). Along each parallel the water starts at the west edge as
// at the bin's south-west corner, flipped by every outline that ends on the west edge below it,
// and then flips at every crossing of an outline: an outline separates a level from the next, so
// that water (even) and land (odd) alternate across it whatever the levels.
template <typename Points>
void raster_bin(const Bin& bin, const gshhg::Grid& grid, const GeoWindow& window, int subrows, int first_row,
                int end_row, const Points& dlon, const Points& dlat, std::vector<float>& water) {
  const double bin_deg = grid.bin_deg(), lat_sw = bin.place.lat_sw(grid), lon_sw = bin.place.lon_sw(grid);
  const double row_deg = (window.north_deg - window.south_deg) / (double(window.height) * subrows);
  const double column_deg = (window.east_deg - window.west_deg) / window.width;
  const int total_subrows = window.height * subrows;
  // Sub-row m lies at latitude north - (m + 0.5) row_deg; those in [lat_sw, lat_sw + bin).
  // Only the pixel rows [first_row, end_row) are written.
  const int m_first =
      std::max(first_row * subrows, int(std::floor((window.north_deg - lat_sw - bin_deg) / row_deg - 0.5)));
  const int m_last = std::min(std::min(end_row * subrows, total_subrows) - 1,
                              int(std::ceil((window.north_deg - lat_sw) / row_deg - 0.5)));
  std::vector<int> rows;
  std::vector<double> heights;  // the sub-rows' heights in the bin, in point units
  for (int m = m_first; m <= m_last; ++m) {
    const double lat = window.north_deg - (m + 0.5) * row_deg;
    if (lat < lat_sw || lat >= lat_sw + bin_deg) continue;
    rows.push_back(m);
    heights.push_back((lat - lat_sw) / bin_deg * gshhg::bin_units);
  }
  if (rows.empty()) return;
  // The sub-rows run north to south: their heights fall by `spacing` point units each.
  const int count = int(rows.size());
  const double top = heights.front(), spacing = row_deg / bin_deg * gshhg::bin_units;

  std::vector<std::vector<double>> crossings(static_cast<std::size_t>(count));
  std::vector<double> west_ends;
  for (const Segment& segment : bin.segments) {
    const std::size_t first = segment.points.start, last = first + segment.points.count - 1;
    if (segment.entry == side_west) west_ends.push_back(static_cast<std::uint16_t>(dlat.at(first)));
    if (segment.exit == side_west) west_ends.push_back(static_cast<std::uint16_t>(dlat.at(last)));
    double x0 = static_cast<std::uint16_t>(dlon.at(first)), y0 = static_cast<std::uint16_t>(dlat.at(first));
    for (std::size_t p = first + 1; p <= last; ++p) {
      const double x1 = static_cast<std::uint16_t>(dlon.at(p)), y1 = static_cast<std::uint16_t>(dlat.at(p));
      const double low = std::min(y0, y1), high = std::max(y0, y1);
      if (high > low) {
        // Sub-rows k with height in [low, high): height(k) = top - k spacing.
        const int k_first = std::max(0, int(std::floor((top - high) / spacing)));
        const int k_last = std::min(count - 1, int(std::ceil((top - low) / spacing)));
        for (int k = k_first; k <= k_last; ++k) {
          const double y = heights[std::size_t(k)];
          if (y < low || y >= high) continue;
          crossings[std::size_t(k)].push_back(x0 + (y - y0) * (x1 - x0) / (y1 - y0));
        }
      }
      x0 = x1;
      y0 = y1;
    }
  }
  std::sort(west_ends.begin(), west_ends.end());

  const double unit_deg = bin_deg / gshhg::bin_units;
  const double share = 1.0 / (column_deg * subrows);
  for (int k = 0; k < count; ++k) {
    const double y = heights[std::size_t(k)];
    const auto below = std::lower_bound(west_ends.begin(), west_ends.end(), y) - west_ends.begin();
    bool wet = bin.south_west_wet != (below % 2 == 1);
    std::vector<double>& xs = crossings[std::size_t(k)];
    std::sort(xs.begin(), xs.end());
    float* row = &water[std::size_t(rows[std::size_t(k)] / subrows) * window.width];
    double from = 0.0;
    for (std::size_t c = 0; c <= xs.size(); ++c) {
      const double to = c < xs.size() ? xs[c] : gshhg::bin_units;
      if (wet && to > from) {
        // The water from `from` to `to` (point units), clipped to the window, into its pixels.
        const double a = std::max(lon_sw + from * unit_deg, window.west_deg);
        const double b = std::min(lon_sw + to * unit_deg, window.east_deg);
        if (b > a) {
          const int i_first = std::max(0, int((a - window.west_deg) / column_deg));
          const int i_last = std::min(window.width - 1, int((b - window.west_deg) / column_deg));
          for (int i = i_first; i <= i_last; ++i) {
            const double left = window.west_deg + i * column_deg;
            const double overlap = std::min(b, left + column_deg) - std::max(a, left);
            if (overlap > 0.0) row[i] += float(overlap * share);
          }
        }
      }
      wet = !wet;
      from = to;
    }
  }
}

}  // namespace

core::ImageData read_gshhg_water(const std::string& path, const GeoWindow& window_in, int subrows) {
  GeoWindow window = window_in;
  gshhg::check_window("read_gshhg_water", window.south_deg, window.north_deg, window.west_deg, window.east_deg);
  if (window.width < 1 || window.height < 1 || subrows < 1 || window.north_deg <= window.south_deg ||
      window.east_deg <= window.west_deg)
    throw std::invalid_argument("read_gshhg_water: the window has no pixels");
  // The pixels keep their latitudes when the window was clamped to the poles.
  window.south_deg = window_in.south_deg;
  window.north_deg = window_in.north_deg;

  const gshhg::NcFile file(path, "GSHHG shoreline file");
  const gshhg::Grid grid = gshhg::read_grid(file);
  const gshhg::Var bin_first_seg = gshhg::find_var(file, "Id_of_first_segment_in_a_bin", {NC_INT});
  const gshhg::Var bin_n_seg = gshhg::find_var(file, "N_segments_in_a_bin", {NC_SHORT, NC_INT});
  const gshhg::Var bin_nodes = gshhg::find_var(file, "Embedded_node_levels_in_a_bin", {NC_SHORT, NC_INT});
  const gshhg::Var seg_info = gshhg::find_var(file, "Embedded_npts_levels_exit_entry_for_a_segment", {NC_INT});
  const gshhg::Var seg_first_pt = gshhg::find_var(file, "Id_of_first_point_in_a_segment", {NC_INT});
  const gshhg::Var pt_dlon = gshhg::find_var(file, "Relative_longitude_from_SW_corner_of_bin", {NC_SHORT});
  const gshhg::Var pt_dlat = gshhg::find_var(file, "Relative_latitude_from_SW_corner_of_bin", {NC_SHORT});
  for (const gshhg::Var* v : {&bin_first_seg, &bin_n_seg, &bin_nodes}) gshhg::expect_length(*v, grid.n_bins);
  for (const gshhg::Var* v : {&seg_info, &seg_first_pt}) gshhg::expect_length(*v, grid.n_segments);
  for (const gshhg::Var* v : {&pt_dlon, &pt_dlat}) gshhg::expect_length(*v, grid.n_points);

  const double lat_low = std::max(window.south_deg, -90.0), lat_high = std::min(window.north_deg, 90.0);
  const std::vector<gshhg::PlacedBin> placed =
      gshhg::window_bins(grid, lat_low, lat_high, window.west_deg, window.east_deg);
  core::ImageData water{window.width, window.height, 1,
                        std::vector<float>(std::size_t(window.width) * window.height, 0.0f)};
  if (placed.empty()) return water;

  std::vector<Run> bin_runs;
  for (const gshhg::PlacedBin& bin : placed) bin_runs.push_back({bin.index, 1});
  const SparseColumn<int> first_seg(bin_first_seg, bin_runs);
  const SparseColumn<int> n_seg(bin_n_seg, bin_runs);
  const SparseColumn<int> nodes(bin_nodes, bin_runs);

  std::vector<Bin> bins;
  std::vector<Run> seg_runs;
  for (const gshhg::PlacedBin& place : placed) {
    const int first = first_seg.at(place.index), count = n_seg.at(place.index);
    if (first < 0 || count < 0 || static_cast<long>(first) + count > grid.n_segments)
      file.fail("bin " + std::to_string(place.index) + " has an invalid segment range");
    Bin bin;
    bin.place = place;
    bin.south_west_wet = ((nodes.at(place.index) >> 9) & 7) % 2 == 0;
    bins.push_back(std::move(bin));
    seg_runs.push_back({static_cast<std::size_t>(first), static_cast<std::size_t>(count)});
  }
  const SparseColumn<int> info(seg_info, seg_runs);
  const SparseColumn<int> first_pt(seg_first_pt, seg_runs);
  std::vector<Run> pt_runs;
  for (std::size_t b = 0; b < bins.size(); ++b)
    for (std::size_t s = seg_runs[b].start; s < seg_runs[b].start + seg_runs[b].count; ++s) {
      const int code = info.at(s), first = first_pt.at(s);
      if (((code >> 6) & 7) == level_grounding_line) continue;
      Segment segment;
      segment.points = {static_cast<std::size_t>(std::max(first, 0)), static_cast<std::size_t>(code >> 9)};
      segment.entry = (code >> 3) & 7;
      segment.exit = code & 7;
      if (first < 0 || segment.points.count < 2 ||
          static_cast<long>(first) + static_cast<long>(segment.points.count) > grid.n_points)
        file.fail("segment " + std::to_string(s) + " has an invalid point range");
      bins[b].segments.push_back(segment);
      pt_runs.push_back(segment.points);
    }
  const SparseColumn<short> dlon(pt_dlon, pt_runs);
  const SparseColumn<short> dlat(pt_dlat, pt_runs);

  // The pixel rows are shared among threads; each takes the bins that reach its rows and writes
  // only those rows (a bin row across two threads' rows is rastered by both, each its part).
  const double row_deg = (window.north_deg - window.south_deg) / window.height;
  core::parallel_rows(window.height, [&](int begin, int end) {
    const double north = window.north_deg - begin * row_deg, south = window.north_deg - end * row_deg;
    for (const Bin& bin : bins) {
      const double lat_sw = bin.place.lat_sw(grid);
      if (lat_sw >= north || lat_sw + grid.bin_deg() <= south) continue;
      raster_bin(bin, grid, window, subrows, begin, end, dlon, dlat, water.pixels);
    }
  });
  for (float& value : water.pixels) value = std::min(value, 1.0f);
  return water;
}

}  // namespace nephele::io
