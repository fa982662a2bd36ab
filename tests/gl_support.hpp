#pragma once
// Test support: one headless OpenGL context per test process, and the probes of src/gpu/probe.hpp
// run in it.
#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include <string>
#include <vector>

#include "gpu/compute_program.hpp"
#include "gpu/egl_context.hpp"
#include "gpu/probe.hpp"

namespace nephele::test {

gpu::EglContext& test_context();

using gpu::GlslTypeName;
using gpu::probe_source;
using gpu::run_probe;

template <class Out, class In>
std::vector<Out> probe(const std::string& includes, const std::string& expression, const std::vector<In>& inputs,
                       const std::string& helpers = "", const std::vector<glm::vec4>& data = {},
                       gpu::ProbeData kind = gpu::ProbeData::buffer) {
  test_context();
  return gpu::probe<Out>(includes, expression, inputs, helpers, data, kind);
}

}  // namespace nephele::test
