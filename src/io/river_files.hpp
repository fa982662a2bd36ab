#pragma once
// Reader of the river lines of GSHHG's binned netCDF files (Debian's gmt-gshhg-full installs
// /usr/share/gmt-gshhg/binned_river_f.nc; docs/terrain.md, Land cover).
//
// Data: CIA World Data Bank II rivers as packaged in GSHHG 2.3.x for GMT.
// The file tiles the globe into square bins (1 degree for the "f" file) and
// stores, per bin, the pieces ("segments") of river polylines that fall inside
// it.  A river crossing a bin edge is therefore split into several segments
// whose end/start points coincide exactly on the shared edge.  This reader
// returns the segments as they are stored; it does not join them.
#include <string>
#include <utility>
#include <vector>

namespace nephele::io {

// Where gmt-gshhg-full (scripts/debian-packages.txt) installs the full-resolution rivers.
inline const char* const gshhg_rivers_default_path = "/usr/share/gmt-gshhg/binned_river_f.nc";

// One stored river segment.
struct RiverLine {
  // WDB II river class as stored in Hierarchial_level_of_a_segment.  These are
  // the same numbers GMT's `coast -I<n>` uses:
  //   0 double-lined rivers (river-lake banks)   5 intermittent rivers, major
  //   1 permanent major rivers                   6 intermittent rivers, additional
  //   2 additional major rivers                  7 intermittent rivers, minor
  //   3 additional rivers                        8 major canals
  //   4 minor rivers                             9 minor canals
  //                                             10 irrigation canals
  int level = 0;
  // (latitude_deg, longitude_deg), consecutive vertices of one polyline.
  // Longitudes are in the frame of the query window: a bin is reported at the
  // multiple-of-360 shift that makes it overlap [west, east], so a query with
  // west < 0 yields negative longitudes west of Greenwich; with 0 <= west the
  // values are the stored ones in [0, 360].  Overall range: [-180, 360].
  std::vector<std::pair<double, double>> points;
};

// Every river segment whose bin intersects [south, north] x [west, east]
// (degrees; the overlap must have positive area unless the window is
// degenerate, so bins that merely touch a window edge are skipped -- they add
// nothing, since edge points are stored in both neighbouring bins) and whose
// level satisfies 0 <= level <= max_level.  Segments are NOT clipped to the
// window.  Zero-length segments (2-point stubs repeating one bin-edge point,
// 38% of the stored segments) are skipped.  Note the class numbering is not a pure
// importance scale: max_level = 4 gives all permanent rivers (0-4) including
// river-lake banks (0), max_level = 10 gives everything.
//
// west/east may be given in -180..180 or 0..360; require west <= east and
// east - west <= 360.  Latitudes are clamped to [-90, 90].
//
// Reads only the bin index entries of the needed latitude rows, the segment
// records of the selected bins and the points of the selected segments.
//
// Throws std::invalid_argument for a bad window (non-finite, south > north,
// west > east), and std::runtime_error naming the file for I/O problems
// (missing/unreadable file, missing variable, unexpected type or shape,
// inconsistent indices).
std::vector<RiverLine> read_gshhg_rivers(const std::string& path, double south_deg, double north_deg, double west_deg,
                                         double east_deg, int max_level);

}  // namespace nephele::io
