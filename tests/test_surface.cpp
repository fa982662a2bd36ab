// The land/ocean mask (--surface): the bias's terms on synthetic masks and on ETOPO5, the
// density pass's use of it, and bad masks (docs/climate.md, "Land and ocean").
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "steady_cover.hpp"
#include "cli_support.hpp"
#include "core/error.hpp"
#include "cover_texels.hpp"
#include "cover/latitude_profile.hpp"
#include "cover/surface_bias.hpp"
#include "shader_math/shader_math.hpp"
#include "gl_support.hpp"
#include "io/elevation_files.hpp"
#include "files/image_files.hpp"
#include "io/surface_files.hpp"

using namespace nephele;

namespace {

// A mask on the bias grid from a land predicate of (latitude, longitude) in degrees.
template <class Land>
cover::SurfaceMask synthetic(Land land) {
  cover::SurfaceMask m{cover::surface_bias_columns, cover::surface_bias_rows, {}, "synthetic"};
  for (int j = 0; j < m.rows; ++j)
    for (int i = 0; i < m.columns; ++i) {
      const double latitude = 90.0 - (j + 0.5) * 180.0 / m.rows, longitude = -180.0 + (i + 0.5) * 360.0 / m.columns;
      m.land.push_back(land(latitude, longitude) ? 1.0f : 0.0f);
    }
  return m;
}

// The bias at the cell holding (latitude, longitude).
float bias_at(const std::vector<float>& bias, double latitude, double longitude) {
  const int j = std::clamp(int((90.0 - latitude) / 180.0 * cover::surface_bias_rows), 0, cover::surface_bias_rows - 1);
  const int i = int((longitude + 180.0) / 360.0 * cover::surface_bias_columns) % cover::surface_bias_columns;
  return bias[static_cast<size_t>(j) * cover::surface_bias_columns + i];
}

// A continent from 0 to 60 degrees east, 45 S to 45 N.
bool continent(double latitude, double longitude) {
  return longitude >= 0 && longitude <= 60 && std::abs(latitude) <= 45;
}

}  // namespace

TEST_CASE("the surface bias is zero over open ocean and the desert weight over wide land", "[fast][surface]") {
  // The filters (weights summing to 1) keep a constant field: 0 for all ocean. All land, every
  // cell infinitely far from the sea, gives -max(S(lat), S_interior(lat)) blurred along latitude
  // by a 2.2-degree kernel: at the peaks (24 and 43 degrees) the curvature 2/64 per degree^2
  // lowers it by about sigma^2 / 32 = 0.08 (0.1 allowed); at 70 degrees both weights are below
  // exp(-11), and the kernel reaches 7 degrees at most: below 1e-4.
  const auto ocean = cover::surface_bias(synthetic([](double, double) { return false; }));
  for (float b : ocean) REQUIRE(b == 0.0f);
  const auto land = cover::surface_bias(synthetic([](double, double) { return true; }));
  CHECK(bias_at(land, 24.25, 0) == Approx(-1.0).margin(0.1));
  CHECK(bias_at(land, -24.25, 100) == Approx(-1.0).margin(0.1));
  CHECK(bias_at(land, 43.25, 200) == Approx(-1.0).margin(0.1));
  CHECK(std::abs(bias_at(land, 70.25, 0)) < 1e-4);
  CHECK(cover::desert_weight(24.0) == 1.0);
  CHECK(cover::deck_weight(-22.0) == 1.0);
  CHECK(cover::interior_weight(-43.0) == 1.0);
  CHECK(cover::inland(500.0) == 0.0);
  CHECK(cover::inland(1000.0) == 0.5);
  CHECK(cover::inland(1500.0) == 1.0);
}

TEST_CASE("the distance to the ocean is the path through the grid, exact along a latitude circle", "[fast][surface]") {
  // Ocean west of Greenwich, land east of it: along the equator and along 60 N the nearest ocean
  // cell lies due west, so the distance is the east-west arc to the coast's ocean cell centre,
  // R cos(lat) dlon, exact for a path along the row (to within the half-cell where the coast
  // falls: 0.25 degrees of longitude); a path leaving the row is no shorter on a grid of
  // eight neighbours.
  const auto grid = synthetic([](double, double longitude) { return longitude > 0 && longitude < 180; });
  const auto distance = cover::ocean_distance_km(grid);
  const auto at = [&](double latitude, double longitude) { return bias_at(distance, latitude, longitude); };
  const double degree_km = 6371.0 * M_PI / 180.0;
  for (double latitude : {0.25, 60.25}) {
    const double per_degree = degree_km * std::cos(latitude * M_PI / 180.0);
    for (double east : {10.25, 40.25}) {
      INFO("latitude " << latitude << ", " << east << " degrees east of the coast");
      CHECK(at(latitude, east) == Approx((east + 0.25) * per_degree).margin(0.5 * per_degree));
    }
  }
  CHECK(at(0.25, -10.25) == 0.0f);  // the ocean itself
  // No ocean at all: infinitely far.
  for (float d : cover::ocean_distance_km(synthetic([](double, double) { return true; }))) REQUIRE(std::isinf(d));
}

TEST_CASE("a continent's mid-latitude interior is dry far from the sea and not near its coasts", "[fast][surface]") {
  // A continent from 0 to 120 E, 20 to 70 N: at 45 N 60 E the sea is 25 degrees away (2780 km),
  // so the whole interior weight S_interior(45) = exp(-1/16) = 0.94 clears it, less the blur's
  // rounding of the weight's peak (its curvature 0.026 per degree^2 times sigma^2 / 2 = 2.4:
  // 0.06; 0.08 allowed, as for the deserts' peak); 3 degrees from its
  // west coast (236 km) the inland factor is 0 within the blur's reach (7 degrees at most, where
  // the coast is 550 km away at most: inland below 0.01), and south of 30 N the subtropical
  // desert weight takes over as before.
  const auto bias = cover::surface_bias(synthetic([](double latitude, double longitude) {
    return longitude >= 0 && longitude <= 120 && latitude >= 20 && latitude <= 70;
  }));
  CHECK(bias_at(bias, 45.0, 60.0) == Approx(-cover::interior_weight(45.0)).margin(0.08));
  CHECK(std::abs(bias_at(bias, 45.0, 3.0)) < 0.02);
  CHECK(bias_at(bias, 50.0, 60.0) < bias_at(bias, 50.0, 10.0));
}

TEST_CASE("a continent gets a desert inside and a deck off its west coast, none off its east coast",
          "[fast][surface]") {
  const auto bias = cover::surface_bias(synthetic(continent));
  // Inside, at 24 N 30 E: the desert term, -1 but for the blur (> 20 degrees from any coast).
  CHECK(bias_at(bias, 24.0, 30.0) < -0.8);
  // 3 degrees off the west coast at 22 S: land 3 degrees east weighted 1 - 3/15 = 0.8, open
  // ocean to the west (W = 1), deck weight 1: 0.8 before the blur, which mixes in the land's
  // -1 within a few cells of the coast: above 0.3.
  CHECK(bias_at(bias, -22.0, -3.0) > 0.3);
  CHECK(bias_at(bias, 22.0, -3.0) > 0.3);
  // Off the east coast and far from any coast: no term (the blur reaches 7 degrees at most).
  CHECK(std::abs(bias_at(bias, 22.0, 70.0)) < 1e-6);
  CHECK(std::abs(bias_at(bias, 0.0, -120.0)) < 1e-6);
  // Beyond the subtropics the desert weight fades: inside the land at 40 N, S(40) = exp(-4) =
  // 0.018 (raised by the blur where S is convex: +0.01), and the land there is 5 degrees (556 km)
  // from the north coast, where the interior term is 0.87 inland(556 km) = 0.008; the blur mixes
  // in the drier interior within 7 degrees to the south (at 35 N, 1112 km inland, 0.37 x 0.66 =
  // 0.24, with a weight of a few per cent): below 0.1.
  CHECK(std::abs(bias_at(bias, 40.0, 30.0)) < 0.1);
}

TEST_CASE("a deck's own term reaches a desert's west coast where the bias falls through zero offshore",
          "[fast][surface]") {
  const cover::SurfaceMask mask = synthetic(continent);
  const std::vector<float> terms = cover::surface_terms(mask), bias = cover::surface_bias(mask);
  REQUIRE(terms.size() == 3 * bias.size());
  std::vector<float> deck(bias.size()), desert(bias.size()), sea(bias.size());
  for (size_t k = 0; k < bias.size(); ++k) {
    deck[k] = terms[3 * k], desert[k] = terms[3 * k + 1], sea[k] = terms[3 * k + 2];
    REQUIRE(deck[k] >= 0.0f);
    REQUIRE(desert[k] >= 0.0f);
    REQUIRE(sea[k] >= 0.0f);
    REQUIRE(sea[k] <= 1.0f + 1e-6f);
    REQUIRE(bias[k] == deck[k] - desert[k]);
  }
  // Half a degree off the west coast at 22 N: before the blur the deck term is 1 x 0.97 on the
  // ocean side and 0 on the land, the desert term 0 and 1 (S_desert(22) = 0.94); the 2.2-degree
  // blur leaves each about half of that at the coast, a little more of the near side's: the deck
  // term above 0.35 (0.4 is a full deck, weather_systems.glsl), while the bias, their difference,
  // is near 0 there (below 0.15: strength 0.4 at most).
  CHECK(bias_at(deck, 22.0, -0.5) > 0.35);
  CHECK(bias_at(bias, 22.0, -0.5) < 0.15);
  // Further out both agree: the desert's blur does not reach 8 degrees.
  CHECK(bias_at(deck, 22.0, -8.0) == Approx(bias_at(bias, 22.0, -8.0)).margin(1e-6));
  // The sea's share (where the storm tracks' open cells form): 1 - land under the same blur, so
  // all sea 8 degrees off the coast, none 8 degrees inland, about half at the coast.
  CHECK(bias_at(sea, 22.0, -8.0) == Approx(1.0).margin(1e-6));
  CHECK(bias_at(sea, 22.0, 8.0) == Approx(0.0).margin(1e-6));
  CHECK(bias_at(sea, 22.0, 0.0) == Approx(0.5).margin(0.15));
}

TEST_CASE(
    "ETOPO5's bias clears the Sahara and puts decks off the west coasts and none on seas with a coast to their west",
    "[fast][surface][terrain]") {
  if (!std::filesystem::exists(io::etopo5_default_path))
    FAIL("ferret-datasets is not installed (scripts/debian-packages.txt)");
  const auto mask = io::surface_from_option("etopo5", nullptr);
  REQUIRE(mask != nullptr);
  const auto bias = cover::surface_bias(*mask);
  CHECK(bias_at(bias, 23.0, 10.0) < -0.7);    // central Sahara
  CHECK(bias_at(bias, -25.0, 135.0) < -0.7);  // central Australia
  CHECK(bias_at(bias, 28.0, -120.0) > 0.2);   // off Baja California
  CHECK(bias_at(bias, -18.0, -78.0) > 0.2);   // off Peru
  CHECK(bias_at(bias, -20.0, 9.0) > 0.2);     // off Namibia
  CHECK(bias_at(bias, 25.0, -18.0) > 0.2);    // off the Canaries
  CHECK(bias_at(bias, -25.0, 110.0) > 0.2);   // off Western Australia
  // No decks on seas with a coast close to their west (land to their east as the decks' oceans):
  CHECK(bias_at(bias, 15.0, 65.0) < 0.05);             // the Arabian Sea
  CHECK(bias_at(bias, 15.0, 88.0) < 0.05);             // the Bay of Bengal
  CHECK(bias_at(bias, -20.0, 40.0) < 0.05);            // the Mozambique Channel
  CHECK(bias_at(bias, 25.0, -90.0) < 0.05);            // the Gulf of Mexico
  CHECK(std::abs(bias_at(bias, 0.0, -150.0)) < 0.05);  // mid-Pacific
  CHECK(std::abs(bias_at(bias, 50.0, 10.0)) < 0.05);   // central Europe: the sea within 500 km
  CHECK(bias_at(bias, 39.0, 83.0) < -0.6);             // the Taklamakan, 2000 km and more from any sea
  CHECK(bias_at(bias, 48.0, 72.0) < -0.5);             // the Kazakh steppe
  CHECK(std::abs(bias_at(bias, 62.0, 100.0)) < 0.05);  // central Siberia: beyond the dry belt
}

TEST_CASE("the density pass moves clouds from a continent's desert to the deck off its coast", "[surface][pass]") {
  // The cloudy fraction (cover > 0) in a box inside the desert and in a box off the west coast,
  // with and without the mask; the calibration keeps each band's coverage, so the clouds move.
  auto fractions = [](bool with_mask) {
    cover::CoverParameters p = test::steady_cover();
    p.size = 64;
    p.curl_size = 64;
    if (with_mask) p.surface = std::make_shared<const cover::SurfaceMask>(synthetic(continent));
    double desert = 0, deck = 0;
    int desert_texels = 0, deck_texels = 0;
    for (const test::CoverTexel& t : test::cover_texels(p)) {
      const double latitude = std::asin(t.direction.z) * 180 / M_PI;
      const double longitude = std::atan2(t.direction.y, t.direction.x) * 180 / M_PI;
      if (std::abs(std::abs(latitude) - 24) < 6 && longitude > 15 && longitude < 45)
        desert += t.cover > 0, ++desert_texels;
      if (std::abs(std::abs(latitude) - 22) < 6 && longitude > -6 && longitude < -1) deck += t.cover > 0, ++deck_texels;
    }
    return std::pair{desert / desert_texels, deck / deck_texels};
  };
  const auto [desert_without, deck_without] = fractions(false);
  const auto [desert_with, deck_with] = fractions(true);
  INFO("desert " << desert_without << " -> " << desert_with << ", deck " << deck_without << " -> " << deck_with);
  // The density factor is 0.6 in the desert and up to 1.3 on the deck (k = 0.4): the desert
  // keeps only its densest noise, the deck gains most of its texels (measured: desert 0.49 ->
  // 0.04, deck 0.34 -> 0.81).
  CHECK(desert_with < 0.5 * desert_without);
  CHECK(deck_with > deck_without + 0.1);
}

TEST_CASE("with a map the February cover is brighter along the SPCZ's line than without it", "[surface][pass]") {
  // The bright fraction (cover above 1/2) within 2 degrees of the SPCZ's mean line over its whole
  // extent (155 E to 156 W), with the SPCZ and without (--spcz 0), over a planet of ocean: its band
  // multiplies the density along the line by 1.25 to 1.5 (half its depth outside the superclusters)
  // and its systems' cores by 1.5, and the calibration, which keeps each latitude band's coverage,
  // takes the cloud from the rest of the band's latitudes. Measured: 0.14 without, 0.53 with.
  const double degree = M_PI / 180.0;
  auto fraction = [&](float spcz) {
    cover::CoverParameters p = test::steady_cover();
    p.size = 64;
    p.curl_size = 64;
    p.month = 2;
    p.spcz = spcz;
    p.surface = std::make_shared<const cover::SurfaceMask>(synthetic([](double, double) { return false; }));
    double on_line = 0;
    int on_texels = 0;
    for (const test::CoverTexel& t : test::cover_texels(p)) {
      const double s = glsl::spcz_along(t.direction);
      const double latitude = std::asin(t.direction.z);
      const double off = latitude - glsl::spcz_latitude(float(s), float(cover::seasonal_shift_deg(-15.0, 2) * degree));
      if (s > 0.05 && s < 0.6 && std::abs(off) < 2.0 * degree) on_line += t.cover > 0.5, ++on_texels;
    }
    return on_line / on_texels;
  };
  const double without = fraction(0.0f), with = fraction(1.0f);
  INFO("bright on the line " << without << " without the SPCZ, " << with << " with it");
  CHECK(with > without + 0.15);
}

TEST_CASE(
    "generate takes ETOPO5's mask by default and records the surface in cover.json and refuses a bad mask "
    "naming --surface",
    "[surface][cli][bad-input]") {
  test::TemporaryDirectory directory(true);
  const auto out = directory.path / "cover";
  const auto earth = test::run("generate --size 8 --curl-size 8 --files png --out " + out.string());
  REQUIRE(earth.exit_code == 0);
  CHECK(test::read_file(out / "cover.json").find("\"surface\": \"etopo5\"") != std::string::npos);
  const auto none = test::run("generate --size 8 --curl-size 8 --files png --surface none --out " +
                              (directory.path / "bare").string());
  REQUIRE(none.exit_code == 0);
  CHECK(test::read_file(directory.path / "bare" / "cover.json").find("\"surface\": \"none\"") != std::string::npos);
  const auto missing = test::run("generate --size 8 --surface " + (directory.path / "absent.png").string() + " --out " +
                                 (directory.path / "x").string());
  CHECK(missing.exit_code == 2);
  CHECK(missing.output.find("--surface") != std::string::npos);
  CHECK(!std::filesystem::exists(directory.path / "x"));
  // A file that is no image names --surface too.
  const auto text = directory.path / "mask.png";
  { std::ofstream(text) << "not an image"; }
  const auto unreadable =
      test::run("generate --size 8 --surface " + text.string() + " --out " + (directory.path / "w").string());
  CHECK(unreadable.exit_code == 2);
  CHECK(unreadable.output.find("--surface") != std::string::npos);
  // Values above 1 in the first channel are no land fractions.
  core::ImageData image{4, 2, 1, std::vector<float>(8, 0.0f)};
  image.pixels[5] = 2.0f;
  const auto mask = directory.path / "mask.exr";
  files::write_image(mask, image, files::exr_encoding({"Y"}));
  const auto bad =
      test::run("generate --size 8 --surface " + mask.string() + " --out " + (directory.path / "y").string());
  CHECK(bad.exit_code == 2);
  CHECK(bad.output.find("--surface") != std::string::npos);
  CHECK(bad.output.find("[0, 1]") != std::string::npos);
  // A valid image mask is taken and named in the sidecar.
  image.pixels[5] = 1.0f;
  files::write_image(mask, image, files::exr_encoding({"Y"}));
  const auto taken = test::run("generate --size 8 --curl-size 8 --files png --surface " + mask.string() + " --out " +
                               (directory.path / "z").string());
  REQUIRE(taken.exit_code == 0);
  CHECK(test::read_file(directory.path / "z" / "cover.json").find(mask.string()) != std::string::npos);
}
