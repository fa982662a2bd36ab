// The reference solution of the warp honours a time budget and reports its own error.
#include <catch2/catch.hpp>

#include <chrono>

#include "cover/cover_parameters.hpp"
#include "studies/reference_flow.hpp"

using namespace nephele;

namespace {

struct DefaultFlow {
  cover::CoverParameters p;
  glsl::CurlParams curl = cover::curl_params(p);
  glm::vec3 offset = cover::potential_offset(p);
  double flow_time = static_cast<double>(p.iterations) * p.step;
};

}  // namespace

TEST_CASE("the reference's error estimate is positive and within its tolerance per accepted step", "[fast][report]") {
  const DefaultFlow flow;
  studies::ReferenceOptions options;
  options.tolerance = 1e-9;
  const auto point =
      studies::reference_warp(glm::dvec3(0.3, -0.5, 0.8), flow.curl, flow.offset, flow.flow_time, options);
  REQUIRE(point.converged);
  CHECK_FALSE(point.cut);
  CHECK(point.error_estimate > 0.0);
  // Every accepted step's estimate is at most the tolerance, and there are at most `steps`.
  CHECK(point.error_estimate <= options.tolerance * static_cast<double>(point.steps));
}

TEST_CASE("a reference past its deadline leaves its points unconverged and marked cut", "[fast][report]") {
  const DefaultFlow flow;
  studies::ReferenceOptions options;
  options.deadline = std::chrono::steady_clock::now() - std::chrono::seconds(1);
  const auto points = studies::reference_warps({glm::vec3(1, 0, 0), glm::vec3(0, 0, 1)}, flow.curl, flow.offset,
                                               flow.flow_time, options);
  for (const auto& p : points) {
    CHECK(p.cut);
    CHECK_FALSE(p.converged);
  }
}
