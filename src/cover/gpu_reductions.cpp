#include "cover/gpu_reductions.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <tuple>

#include "cover/latitude_profile.hpp"
#include "gpu/shader_bindings.hpp"
#include "gpu/storage_buffer.hpp"

namespace nephele::cover {
namespace {

double area_antiderivative(double x, double y) { return std::atan2(x * y, std::sqrt(1.0 + x * x + y * y)); }

// A shader storage buffer of 32-bit words, created zeroed.
class WordBuffer {
 public:
  explicit WordBuffer(size_t words) : buffer_(words * 4), words_(words) { clear(); }
  void clear() const {
    const GLuint zero = 0;
    glClearNamedBufferData(buffer_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  }
  void set(size_t word, GLuint value) const { buffer_.write(&value, 4, word * 4); }
  void bind(GLuint binding) const { buffer_.bind(binding); }
  std::vector<GLuint> read(size_t words) const {
    std::vector<GLuint> out(std::min(words, words_));
    buffer_.read(out.data(), out.size() * 4);
    return out;
  }

 private:
  gpu::StorageBuffer buffer_;
  size_t words_;
};

float from_sortable(GLuint bits) {
  const GLuint raw = (bits & 0x80000000u) ? bits & 0x7FFFFFFFu : ~bits;
  float value;
  std::memcpy(&value, &raw, sizeof value);
  return value;
}

std::vector<std::uint64_t> sums64(const std::vector<GLuint>& words) {
  std::vector<std::uint64_t> sums(words.size() / 2);
  for (size_t k = 0; k < sums.size(); ++k)
    sums[k] = words[2 * k] | (static_cast<std::uint64_t>(words[2 * k + 1]) << 32);
  return sums;
}

constexpr int bins = 4096;  // per level, as cover::calibrate_coverage

}  // namespace

DensityParts whole_cube(const gpu::Texture& density) {
  return [&density](const std::function<void(const DensityPart&)>& use) {
    use(DensityPart{density, CubeRegion::whole(density.width())});
  };
}

int reduction_strip(int size) {
  const long texels = 6L * size * size;
  return static_cast<int>(std::max<long>(32, (texels + (1L << 20) - 1) >> 20));
}

int diagnosis_strip(int size) { return 4 * reduction_strip(size); }

int density_strip(int size) { return std::min(reduction_strip(size), 96); }

double TexelWeightUnits::fraction(std::uint64_t units) const {
  return std::ldexp(static_cast<double>(units), -scale_bits);
}

double TexelWeightUnits::sum_error_bound() const { return 6.0 * size * size * std::ldexp(0.5, -scale_bits); }

TexelWeightUnits texel_weight_units(int size) {
  // The same edges and expression as cover::face_texel_solid_angles, so octant entries are
  // the CPU's values to the bit before rounding to units.
  std::vector<double> edges(static_cast<size_t>(size) + 1);
  for (int k = 0; k <= size; ++k) edges[k] = 2.0 * k / size - 1.0;
  const int half = (size + 1) / 2;
  std::vector<double> fractions;
  fractions.reserve(static_cast<size_t>(half) * (half + 1) / 2);
  // The antiderivative at the edges (a, b) and (a, b + 1), row by row: each corner's value is
  // computed once (not four times), with the same arguments in the same order, so the same bits.
  std::vector<double> row(static_cast<size_t>(half) + 1), next_row(static_cast<size_t>(half) + 1);
  for (int a = 0; a <= 1 && a <= half; ++a) row[a] = area_antiderivative(edges[a], edges[0]);
  for (int b = 0; b < half; ++b) {
    for (int a = 0; a <= b + 1; ++a) next_row[a] = area_antiderivative(edges[a], edges[b + 1]);
    if (b + 1 <= half) row[b + 1] = area_antiderivative(edges[b + 1], edges[b]);
    for (int a = 0; a <= b; ++a)
      fractions.push_back((next_row[a + 1] - next_row[a] - row[a + 1] + row[a]) / (4.0 * M_PI));
    std::swap(row, next_row);
  }
  TexelWeightUnits units;
  units.size = size;
  // The largest texel is at the face's centre, in the octant: the same double as the CPU's.
  const double largest = *std::max_element(fractions.begin(), fractions.end());
  units.largest_fraction = largest;
  units.scale_bits = static_cast<int>(std::floor(31.0 - std::log2(largest)));
  units.octant.resize(fractions.size());
  for (size_t k = 0; k < fractions.size(); ++k)
    units.octant[k] = static_cast<std::uint32_t>(std::llround(std::ldexp(fractions[k], units.scale_bits)));
  return units;
}

double reduction_gpu_bytes(int size) {
  const double half = (size + 1) / 2;
  const double table = half * (half + 1) / 2 * 4.0;
  const int strip = diagnosis_strip(size);                                // the diagnosis's partial records
  const double records = 6.0 * size * ((size + strip - 1) / strip) + 64;  // + stage 1's 64
  const double band_tables = profile_bands * (band_bins * 8.0 + 12.0);    // one histogram, crossings, thresholds
  return 2 * table + calibration_member_capacity * 8.0 + 2 * bins * 8.0 + records * 6 * 8.0 + band_tables;
}

GpuTexelWeights::GpuTexelWeights(int size) : units_(texel_weight_units(size)) {
  GLint most = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &most);
  if (most > 0 && units_.octant.size() > static_cast<size_t>(most))
    throw std::runtime_error("the texel weight table of a face of " + std::to_string(size) + " has " +
                             std::to_string(units_.octant.size()) + " entries, over this driver's " +
                             std::to_string(most) + " buffer texture texels");
  glCreateBuffers(1, &buffer_);
  glNamedBufferStorage(buffer_, static_cast<GLsizeiptr>(units_.octant.size() * 4), units_.octant.data(), 0);
  glCreateTextures(GL_TEXTURE_BUFFER, 1, &texture_);
  glTextureBuffer(texture_, GL_R32UI, buffer_);
}

GpuTexelWeights::~GpuTexelWeights() {
  glDeleteTextures(1, &texture_);
  glDeleteBuffers(1, &buffer_);
}

void GpuTexelWeights::bind() const { glBindTextureUnit(shader_bindings::cover_texel_weights::texel_weights, texture_); }

GpuCalibration::GpuCalibration(int size) : size_(size), weights_(size) {
  glCreateBuffers(1, &band_thresholds_);
  glNamedBufferStorage(band_thresholds_, profile_bands * 4, nullptr, GL_DYNAMIC_STORAGE_BIT);
  glCreateBuffers(1, &band_crossing_);
  glNamedBufferStorage(band_crossing_, profile_bands * 8, nullptr, GL_DYNAMIC_STORAGE_BIT);
  glCreateBuffers(1, &density_range_);
  glNamedBufferStorage(density_range_, 8, nullptr, GL_DYNAMIC_STORAGE_BIT);
  glCreateBuffers(1, &band_cloudy_);
  glNamedBufferStorage(band_cloudy_, profile_bands * 8, nullptr, GL_DYNAMIC_STORAGE_BIT);
  glCreateBuffers(1, &band_tails_);
  glNamedBufferStorage(band_tails_, profile_bands * (band_bins + 1) * 4, nullptr, GL_DYNAMIC_STORAGE_BIT);
}

GpuCalibration::~GpuCalibration() {
  glDeleteBuffers(1, &band_thresholds_);
  glDeleteBuffers(1, &band_crossing_);
  glDeleteBuffers(1, &density_range_);
  glDeleteBuffers(1, &band_cloudy_);
  glDeleteBuffers(1, &band_tails_);
}

void GpuCalibration::bind_density_range() const {
  const GLuint empty[2] = {0xFFFFFFFFu, 0u};
  glNamedBufferSubData(density_range_, 0, sizeof empty, empty);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, shader_bindings::cover_cover_density::density_range, density_range_);
}

void GpuCalibration::dispatch_parts(const DensityParts& parts) const {
  const int strip = reduction_strip(size_);
  program_.set("u_strip", strip);
  parts([&](const DensityPart& part) {
    if (part.region.face_size != size_) throw std::invalid_argument("GpuCalibration: a density part of another size");
    part.density.bind_image_layers(shader_bindings::cover_coverage_histogram::density_field, GL_READ_ONLY);
    set_region(program_, part.region);
    program_.dispatch_covering(size_, (part.region.owned_rows() + strip - 1) / strip, part.region.layers);
  });
}

std::pair<float, float> GpuCalibration::density_range(const DensityParts& parts) const {
  // Stage 0 writes the same two words as the density pass.
  bind_density_range();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, shader_bindings::cover_coverage_histogram::scalars, density_range_);
  weights_.bind();
  program_.set("u_stage", 0);
  dispatch_parts(parts);
  return read_density_range();
}

std::pair<float, float> GpuCalibration::read_density_range() const {
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  GLuint words[2];
  glGetNamedBufferSubData(density_range_, 0, sizeof words, words);
  return {from_sortable(words[0]), from_sortable(words[1])};
}

void GpuCalibration::bind_band_cloudy() const {
  const GLuint zero = 0;
  glClearNamedBufferData(band_cloudy_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, shader_bindings::cover_cover_remap::band_cloudy, band_cloudy_);
  weights_.bind();
}

void GpuCalibration::read_band_cloudy(BandCalibration& c) const {
  const size_t bands = c.thresholds.size();
  std::vector<GLuint> words(2 * bands);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(band_cloudy_, 0, static_cast<GLsizeiptr>(words.size() * 4), words.data());
  set_achieved(sums64(words), c);
}

void GpuCalibration::bind_band_thresholds() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, shader_bindings::cover_band_thresholds::band_thresholds, band_thresholds_);
}

void GpuCalibration::set_band_tails(const std::vector<float>& tails) const {
  if (tails.empty() || tails.size() > static_cast<size_t>(profile_bands) * (band_bins + 1))
    throw std::invalid_argument("GpuCalibration: band tails of more bands than the profile's");
  glNamedBufferSubData(band_tails_, 0, static_cast<GLsizeiptr>(tails.size() * 4), tails.data());
}

void GpuCalibration::bind_band_tails() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, shader_bindings::cover_band_tails::band_tails, band_tails_);
}

std::vector<std::uint64_t> GpuCalibration::band_histogram(const DensityParts& parts, int stage, int bands,
                                                          float density_min, float scale) const {
  const size_t slots = stage == 8 ? bands : static_cast<size_t>(bands) * band_bins;
  WordBuffer histogram(2 * slots);
  histogram.bind(shader_bindings::cover_coverage_histogram::histogram);
  weights_.bind();
  bind_band_thresholds();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, shader_bindings::cover_coverage_histogram::band_crossing, band_crossing_);
  program_.set("u_stage", stage);
  program_.set("u_bands", bands);
  program_.set("u_density_min", density_min);
  program_.set("u_band_scale", scale);
  dispatch_parts(parts);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  return sums64(histogram.read(2 * slots));
}

BandCalibration GpuCalibration::run_bands(const gpu::Texture& density, const std::vector<double>& targets,
                                          bool range_from_density_pass) const {
  if (density.width() != size_) throw std::invalid_argument("GpuCalibration: the density map is not of its size");
  std::optional<std::pair<float, float>> range;
  if (range_from_density_pass) range = read_density_range();
  return run_bands(whole_cube(density), targets, range);
}

BandCalibration GpuCalibration::run_bands(const DensityParts& parts, const std::vector<double>& targets,
                                          std::optional<std::pair<float, float>> range) const {
  const int bands = static_cast<int>(targets.size());
  if (bands < 1 || bands > profile_bands) throw std::invalid_argument("GpuCalibration: bands out of range");
  const TexelWeightUnits& units = weights_.units();
  BandCalibration c;
  c.targets = targets;
  std::tie(c.density_min, c.density_max) = range ? *range : density_range(parts);
  const float scale = band_bin_scale(c.density_min, c.density_max);
  const auto as_fractions = [&](const std::vector<std::uint64_t>& sums) {
    std::vector<double> out(sums.size());
    for (size_t k = 0; k < sums.size(); ++k) out[k] = units.fraction(sums[k]);
    return out;
  };
  c.histogram = as_fractions(band_histogram(parts, 6, bands, c.density_min, scale));
  c.bin_scale = scale;
  const std::vector<BandCrossing> crossings = band_crossings(c.histogram, targets, c.density_min, scale);
  std::vector<GLuint> crossing_words(2 * static_cast<size_t>(bands));
  for (int b = 0; b < bands; ++b) {
    crossing_words[2 * b] = static_cast<GLuint>(crossings[b].bin);
    std::memcpy(&crossing_words[2 * b + 1], &crossings[b].low, 4);
  }
  glNamedBufferSubData(band_crossing_, 0, static_cast<GLsizeiptr>(crossing_words.size() * 4), crossing_words.data());
  const std::vector<double> fine = as_fractions(band_histogram(parts, 7, bands, c.density_min, scale));
  c.thresholds = band_thresholds(crossings, fine, c.density_min, c.density_max, scale);
  glNamedBufferSubData(band_thresholds_, 0, static_cast<GLsizeiptr>(bands * 4), c.thresholds.data());
  c.band_weight.resize(static_cast<size_t>(bands));
  for (int b = 0; b < bands; ++b) c.band_weight[b] = crossings[b].total;
  return c;
}

std::vector<double> GpuCalibration::coarse_histogram(const DensityParts& parts, int bands, float density_min,
                                                     float scale) const {
  const std::vector<std::uint64_t> sums = band_histogram(parts, 6, bands, density_min, scale);
  std::vector<double> out(sums.size());
  for (size_t k = 0; k < sums.size(); ++k) out[k] = weights_.units().fraction(sums[k]);
  return out;
}

void GpuCalibration::measure_bands(const gpu::Texture& density, BandCalibration& c) const {
  const int bands = static_cast<int>(c.thresholds.size());
  glNamedBufferSubData(band_thresholds_, 0, static_cast<GLsizeiptr>(bands * 4), c.thresholds.data());
  set_achieved(band_histogram(whole_cube(density), 8, bands, c.density_min, 0.0f), c);
}

void GpuCalibration::set_achieved(const std::vector<std::uint64_t>& cloudy, BandCalibration& c) const {
  const int bands = static_cast<int>(c.thresholds.size());
  const TexelWeightUnits& units = weights_.units();
  c.achieved.assign(static_cast<size_t>(bands), 0.0);
  std::uint64_t total = 0;
  for (int b = 0; b < bands; ++b) {
    total += cloudy[b];
    c.achieved[b] = c.band_weight[b] > 0.0 ? units.fraction(cloudy[b]) / c.band_weight[b] : 0.0;
  }
  c.achieved_fraction = units.fraction(total);
}

CoverageCalibration GpuCalibration::run(const gpu::Texture& density, double target,
                                        bool range_from_density_pass) const {
  if (density.width() != size_) throw std::invalid_argument("GpuCalibration: the density map is not of its size");
  std::optional<std::pair<float, float>> range;
  if (range_from_density_pass) range = read_density_range();
  return run(whole_cube(density), target, range);
}

CoverageCalibration GpuCalibration::run(const DensityParts& parts, double target,
                                        std::optional<std::pair<float, float>> range) const {
  const TexelWeightUnits& units = weights_.units();
  CoverageCalibration result;
  std::tie(result.density_min, result.density_max) = range ? *range : density_range(parts);
  WordBuffer scalars(8), histogram(2 * bins), members(2 * static_cast<size_t>(calibration_member_capacity));
  scalars.bind(shader_bindings::cover_coverage_histogram::scalars);
  histogram.bind(shader_bindings::cover_coverage_histogram::histogram);
  members.bind(shader_bindings::cover_coverage_histogram::members);
  weights_.bind();
  auto dispatch = [&](int stage) {
    program_.set("u_stage", stage);
    dispatch_parts(parts);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  };
  result.max_texel_fraction = units.largest_fraction;
  // Bin scales in float, 0 where they would not be finite (all densities equal or nearly).
  const auto finite_scale = [](double scale) {
    return std::isfinite(scale) && scale < std::numeric_limits<float>::max() ? static_cast<float>(scale) : 0.0f;
  };
  const double span = static_cast<double>(result.density_max) - result.density_min;
  const float scale = span > 0.0 ? finite_scale(bins / span) : 0.0f;
  program_.set("u_density_min", result.density_min);
  program_.set("u_scale", scale);
  program_.set("u_coarse_low", result.density_min);
  program_.set("u_fine_scale", 0.0f);

  // Walks down from the top bin while the cloudy fraction stays below the target, as the CPU.
  std::uint64_t above = 0;
  auto crossing = [&](const std::vector<std::uint64_t>& weight) {
    int bin = bins - 1;
    while (bin > 0 && units.fraction(above + weight[bin]) < target) above += weight[bin--];
    return bin;
  };
  dispatch(1);
  const int coarse = crossing(sums64(histogram.read(2 * bins)));
  program_.set("u_coarse", coarse);
  if (scale > 0.0f) {
    program_.set("u_coarse_low", static_cast<float>(result.density_min + coarse / static_cast<double>(scale)));
    program_.set("u_fine_scale", finite_scale(static_cast<double>(scale) * bins));
  }
  // The texels of the crossing bin, listed: the coarse bin's (as the CPU sorts them), or where
  // it holds too many, the fine bin's within it.
  dispatch(2);
  int fine = 0;  // the listed texels are those of bins at or above (coarse, fine)
  std::uint64_t listed_weight = 0;
  GLuint count = scalars.read(5)[4];
  if (count > static_cast<GLuint>(calibration_member_capacity)) {
    histogram.clear();
    dispatch(3);
    const std::vector<std::uint64_t> fine_weight = sums64(histogram.read(2 * bins));
    fine = crossing(fine_weight);
    listed_weight = fine_weight[fine];
    program_.set("u_fine", fine);
    scalars.set(3, 0);
    scalars.set(4, 0);
    dispatch(4);
    count = scalars.read(5)[4];
  }
  // The largest density below the listed bin: the threshold when all of it is cloudy.
  auto largest_below = [&] {
    program_.set("u_fine", fine);
    dispatch(5);
    const GLuint bits = scalars.read(3)[2];
    return bits ? from_sortable(bits) : std::nextafter(result.density_min, -INFINITY);
  };

  if (count <= static_cast<GLuint>(calibration_member_capacity)) {
    const std::vector<GLuint> words = members.read(2 * static_cast<size_t>(count));
    std::vector<std::pair<float, GLuint>> list(count);
    for (GLuint k = 0; k < count; ++k) {
      std::memcpy(&list[k].first, &words[2 * k], sizeof(float));
      list[k].second = words[2 * k + 1];
    }
    std::sort(list.begin(), list.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    // The cut nearest the target, the first of equals (as the CPU).
    double best_error = std::abs(units.fraction(above) - target);
    size_t best_count = 0;
    std::uint64_t cumulative = above;
    for (size_t n = 1; n <= list.size(); ++n) {
      cumulative += list[n - 1].second;
      const double error = std::abs(units.fraction(cumulative) - target);
      if (error < best_error) {
        best_error = error;
        best_count = n;
      }
    }
    result.threshold = best_count < list.size() ? list[best_count].first : largest_below();
    std::uint64_t achieved = above;
    for (const auto& m : list)
      if (m.first > result.threshold) achieved += m.second;
    result.achieved_fraction = units.fraction(achieved);
  } else {
    // Too many texels in one fine bin to list: the bin is cloudy or clear as a whole, whichever
    // is nearer the target. (The CPU may cut inside a run of equal densities, which then all
    // count as clear; this is never further from the target.)
    const double none = units.fraction(above), all = units.fraction(above + listed_weight);
    const bool take_all = std::abs(all - target) < std::abs(none - target);
    result.threshold = take_all ? largest_below() : from_sortable(scalars.read(4)[3]);
    result.achieved_fraction = take_all ? all : none;
  }
  return result;
}

GpuDiagnosis::GpuDiagnosis(int size) : size_(size), weights_(size) {}

void DiagnosisSums::add(const DiagnosisSums& o) {
  folded_units += o.folded_units;
  beyond_units += o.beyond_units;
  capped_texels += o.capped_texels;
  off_sphere_texels += o.off_sphere_texels;
  max_attempts = std::max(max_attempts, o.max_attempts);
  max_rate = std::max(max_rate, o.max_rate);
  jacobian_min = std::min(jacobian_min, o.jacobian_min);
  jacobian_max = std::max(jacobian_max, o.jacobian_max);
  error_sum += o.error_sum;
  weight_sum += o.weight_sum;
  attempts_sum += o.attempts_sum;
}

WarpDiagnostics diagnostics_from_sums(const DiagnosisSums& s, const TexelWeightUnits& units, Integrator integrator,
                                      double step, bool moving) {
  const double limit = stability_limit(integrator);
  WarpDiagnostics d;
  d.adaptive = integrator == Integrator::adaptive;
  d.stiffness.step = step;
  d.stiffness.max_rate = s.max_rate;
  d.stiffness.stiffness = step * s.max_rate;
  d.stiffness.limit = limit;
  d.stiffness.beyond_fraction = units.fraction(s.beyond_units);
  const bool measured = s.weight_sum > 0.0;  // size 1: no neighbours, nothing measured
  d.folding.folded_fraction = units.fraction(s.folded_units);
  d.folding.jacobian_min = measured ? s.jacobian_min : 1.0;
  d.folding.jacobian_max = measured ? s.jacobian_max : 1.0;
  d.folding.area_error_rms = measured ? std::sqrt(s.error_sum / s.weight_sum) : 0.0;
  const double texels = 6.0 * units.size * units.size;
  d.substeps.mean_attempts = s.attempts_sum / texels;
  d.substeps.max_attempts = s.max_attempts;
  d.substeps.capped_texels = static_cast<long>(s.capped_texels);
  add_warp_warnings(d, integrator, step, static_cast<long>(s.off_sphere_texels), moving);
  return d;
}

WarpDiagnostics GpuDiagnosis::run(const gpu::Texture& curl, const gpu::Texture& warp, Integrator integrator,
                                  double step, bool moving) const {
  if (curl.width() != size_ || warp.width() != size_)
    throw std::invalid_argument("GpuDiagnosis: the maps are not of its size");
  return diagnostics_from_sums(sums(curl, warp, CubeRegion::whole(size_), integrator, step), weights_.units(),
                               integrator, step, moving);
}

DiagnosisSums GpuDiagnosis::sums(const gpu::Texture& curl, const gpu::Texture& warp, const CubeRegion& region,
                                 Integrator integrator, double step) const {
  if (region.face_size != size_ || warp.width() != size_ || warp.height() != region.rows)
    throw std::invalid_argument("GpuDiagnosis: the maps are not of its region");
  constexpr int figures = 6, group = 64;
  const int strip = diagnosis_strip(size_);
  const int strips = (region.owned_rows() + strip - 1) / strip;
  const int partial_count = strips * size_ * region.layers;
  // Stage 1 writes its 64 intermediate records after the partials.
  WordBuffer counters(8), partials(2 * static_cast<size_t>(figures) * (partial_count + group)), totals(2 * figures);
  namespace diagnostics = shader_bindings::cover_warp_diagnostics;
  counters.bind(diagnostics::counters);
  partials.bind(diagnostics::partials);
  totals.bind(diagnostics::totals);
  weights_.bind();
  curl.bind_image_layers(diagnostics::curl_field, GL_READ_ONLY);
  warp.bind_image_layers(diagnostics::warp_field, GL_READ_ONLY);
  set_region(program_, region);
  const double limit = stability_limit(integrator);
  glProgramUniform1d(program_.id(), glGetUniformLocation(program_.id(), "u_step"), step);
  glProgramUniform1d(program_.id(), glGetUniformLocation(program_.id(), "u_limit"), limit);
  program_.set("u_partials", partial_count);
  program_.set("u_strip", strip);
  program_.set("u_stage", 0);
  program_.dispatch_covering(size_, strips, region.layers);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  program_.set("u_stage", 1);
  program_.use();
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  const std::vector<GLuint> words = counters.read(7);
  const std::vector<GLuint> total_words = totals.read(2 * figures);
  double total[figures];
  std::memcpy(total, total_words.data(), sizeof total);
  const auto units64 = [&](int slot) {
    return words[2 * slot] | (static_cast<std::uint64_t>(words[2 * slot + 1]) << 32);
  };
  DiagnosisSums s;
  s.folded_units = units64(0);
  s.beyond_units = units64(1);
  s.capped_texels = words[4];
  s.off_sphere_texels = words[5];
  s.max_attempts = from_sortable(words[6]);
  s.max_rate = total[0];
  s.jacobian_min = total[1];
  s.jacobian_max = total[2];
  s.error_sum = total[3];
  s.weight_sum = total[4];
  s.attempts_sum = total[5];
  return s;
}

}  // namespace nephele::cover
