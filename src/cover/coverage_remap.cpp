#include "cover/coverage_remap.hpp"

#include "gpu/shader_bindings.hpp"

namespace nephele::cover {

namespace {
bool flat(const CoverParameters& p) { return p.profile.kind == LatitudeProfile::Kind::flat; }
}  // namespace

CoverageRemap::CoverageRemap(const CoverParameters& parameters)
    : parameters_(parameters), calibration_(parameters.size) {}

void CoverageRemap::calibrate(const DensityParts& parts, std::optional<std::pair<float, float>> range) {
  if (flat(parameters_)) {
    result_ = calibration_.run(parts, parameters_.coverage, range);
    bands_.reset();
    // The tails of one band, the sphere, for the optical thickness's ranks: one more histogram.
    tail_bands_ = 1;
    tail_min_ = result_.density_min;
    tail_scale_ = band_bin_scale(result_.density_min, result_.density_max);
    calibration_.set_band_tails(band_tails(calibration_.coarse_histogram(parts, 1, tail_min_, tail_scale_), 1));
    return;
  }
  bands_ =
      calibration_.run_bands(parts, band_targets(parameters_.profile, parameters_.month, parameters_.coverage), range);
  tail_bands_ = profile_bands;
  tail_min_ = bands_->density_min;
  tail_scale_ = bands_->bin_scale;
  calibration_.set_band_tails(band_tails(bands_->histogram, profile_bands));
  result_ = CoverageCalibration{};
  result_.density_min = bands_->density_min;
  result_.density_max = bands_->density_max;
  result_.max_texel_fraction = calibration_.weights().units().largest_fraction;
}

void CoverageRemap::begin_remap() const {
  remap_program_.set("u_threshold", result_.threshold);
  remap_program_.set("u_density_max", result_.density_max);
  remap_program_.set("u_softness", parameters_.cover_softness);
  remap_program_.set("u_bands", flat(parameters_) ? 0 : profile_bands);
  remap_program_.set("u_strip", reduction_strip(parameters_.size));
  remap_program_.set("u_tau_median", parameters_.tau_median);
  remap_program_.set("u_tau_spread", parameters_.tau_spread);
  remap_program_.set("u_tail_bands", tail_bands_);
  remap_program_.set("u_tail_min", tail_min_);
  remap_program_.set("u_tail_scale", tail_scale_);
  calibration_.bind_band_tails();
  if (!flat(parameters_)) {
    calibration_.bind_band_thresholds();
    calibration_.bind_band_cloudy();
  }
}

void CoverageRemap::remap(const gpu::Texture& density, const gpu::Texture& contrast, const CoverFields& fields,
                          const CubeRegion& region) const {
  namespace remap = shader_bindings::cover_cover_remap;
  density.bind_image_layers(remap::density_field, GL_READ_ONLY);
  contrast.bind_image_layers(remap::cover_contrast_field, GL_READ_ONLY);
  fields.cover.bind_image_layers(remap::cover_field, GL_WRITE_ONLY);
  fields.optical_thickness.bind_image_layers(remap::optical_thickness_field, GL_WRITE_ONLY);
  fields.cloud_top.bind_image_layers(remap::cloud_top_field, GL_READ_WRITE);
  set_region(remap_program_, region);
  const int strip = reduction_strip(parameters_.size);
  remap_program_.dispatch_covering(parameters_.size, (region.owned_rows() + strip - 1) / strip, region.layers);
  gpu::image_barrier();
}

const CoverageCalibration& CoverageRemap::finish_remap() {
  // The profile: what the smooth threshold achieves (it blends neighbouring bands, so each
  // band's fraction differs a little from its target), measured by the remap as it wrote.
  if (bands_) {
    calibration_.read_band_cloudy(*bands_);
    result_.achieved_fraction = bands_->achieved_fraction;
  }
  return result_;
}

}  // namespace nephele::cover
