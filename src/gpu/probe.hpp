#pragma once
// Probes: run a GLSL expression on a handful of inputs in one tiny compute dispatch and read the
// values back (the way sfsim tests its shaders). The tests use them to check every function of
// the shader library against its C++ twin; any tool can use them to check a driver.
#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace nephele::gpu {

template <class T>
struct GlslTypeName;
template <>
struct GlslTypeName<glm::vec4> {
  static constexpr const char* name = "vec4";
};
template <>
struct GlslTypeName<glm::uvec4> {
  static constexpr const char* name = "uvec4";
};
// Column-major 4x4 floats: the same 64 bytes in std430 and in glm (inputs of up to 16 numbers).
template <>
struct GlslTypeName<glm::mat4> {
  static constexpr const char* name = "mat4";
};

// Source of a probe shader: `includes` (lines such as #include "../lib/hash.glsl"), optional
// `helpers` (GLSL declarations), and `expression`, evaluated per input with `input_value`
// (of type In) in scope, converted to Out.
std::string probe_source(const std::string& in_type, const std::string& out_type, const std::string& includes,
                         const std::string& helpers, const std::string& expression);

// The probe's buffers: its inputs, its outputs and the data a probe file may read (declared in
// the probe's GLSL at probe_data_binding).
constexpr int probe_inputs_binding = 0, probe_outputs_binding = 1, probe_data_binding = 2;

// How a probe reads its data: a read-only buffer of vec4, or a read-only rgba32f image of six
// square layers (texels layer by layer, rows from t = 0), a cube map (imageCube) or a 2D array
// (image2DArray), at image unit probe_data_binding.
enum class ProbeData { buffer, cube_image, array_image };

// Compiles `source` and runs it over `count` inputs; needs a current OpenGL 4.5 context.
// `data`, when not empty, is bound read-only at probe_data_binding as `kind` says.
void run_probe(const std::string& source, const void* inputs, std::size_t input_bytes, void* outputs,
               std::size_t output_bytes, std::size_t count, const std::vector<glm::vec4>& data = {},
               ProbeData kind = ProbeData::buffer);

template <class Out, class In>
std::vector<Out> probe(const std::string& includes, const std::string& expression, const std::vector<In>& inputs,
                       const std::string& helpers = "", const std::vector<glm::vec4>& data = {},
                       ProbeData kind = ProbeData::buffer) {
  std::vector<Out> outputs(inputs.size());
  run_probe(probe_source(GlslTypeName<In>::name, GlslTypeName<Out>::name, includes, helpers, expression), inputs.data(),
            inputs.size() * sizeof(In), outputs.data(), outputs.size() * sizeof(Out), inputs.size(), data, kind);
  return outputs;
}

}  // namespace nephele::gpu
