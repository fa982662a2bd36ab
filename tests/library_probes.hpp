#pragma once
// The harness of the library probes (tests/probes/NAME.glsl, docs/testing.md): a probe is written
// in the shared GLSL/C++ subset, takes a mat4 x whose x[0].x is the code of the function to run
// (one of the probe's `const int PROBE_... = code;`) and returns a vec4. test_library_probes.cpp
// compares the GPU's results with the C++ twin's, test_probe_closed_forms.cpp with values known
// in closed form.
#include <glm/glm.hpp>

#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "gl_support.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::test {

// One float rounding, relative: 2^-24.
constexpr float kUlp = 1.0f / 16777216.0f;
// Integer results (hashes, cell indices, face numbers) and sign flips: no rounding at all.
constexpr float kExact = 0.0f;
// GLSL allows 2.5 ulp for a division and lets the driver fuse a*b + c (1 ulp more per fused
// pair); the arithmetic probed here chains at most 8 such operations on values below 4:
// 8 x 3.5 ulp x 4 = 112 ulp (6.7e-6).
constexpr float kArithmetic = 8 * 3.5f * 4 * kUlp;
// Driver exp, pow, sin and cos: GLSL 4.50 (section 4.7.1) allows exp/exp2 3 + 2|x| ulp and pow
// that of exp2(y log2 x); with |x| <= 8 here that is at most 19 ulp relative, then the few
// arithmetic operations around them: 32 ulp relative, on results below 4 (absolute 2^-17).
constexpr float kTranscendental = 32 * 4 * kUlp;

// The text of tests/probes/NAME.glsl.
inline std::string probe_text(const std::string& name) {
  std::ifstream in(std::string(NEPHELE_SOURCE_DIR) + "/tests/probes/" + name + ".glsl");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A probe's input: the function's code in x[0].x, then a.xyz in x[0].yzw and b, c, d in x[1..3].
inline glm::mat4 arguments(int function, glm::vec4 a, glm::vec4 b = glm::vec4(0.0f), glm::vec4 c = glm::vec4(0.0f),
                           glm::vec4 d = glm::vec4(0.0f)) {
  glm::mat4 m(0.0f);
  m[0] = glm::vec4(float(function), a.x, a.y, a.z);
  m[1] = b;
  m[2] = c;
  m[3] = d;
  return m;
}

// The names of a probe's function codes, read from its `const int PROBE_NAME = code;` lines (for
// failure messages).
inline std::map<int, std::string> probe_function_names(const std::string& probe) {
  static const std::regex code(R"(const int (PROBE_\w+) = (\d+);)");
  std::map<int, std::string> names;
  for (std::sregex_iterator it(probe.begin(), probe.end(), code), end; it != end; ++it)
    names[std::stoi((*it)[2].str())] = (*it)[1].str();
  return names;
}

// probe_NAME(x) on the GPU for each x of `inputs`, in one dispatch. `data`: the probe's data at
// binding 2 (a cube map, say).
inline std::vector<glm::vec4> run_library_probe(const std::string& name, const std::vector<glm::mat4>& inputs,
                                                const std::vector<glm::vec4>& data = {},
                                                gpu::ProbeData kind = gpu::ProbeData::buffer) {
  return test::probe<glm::vec4>(probe_text(name), "probe_" + name + "(input_value)", inputs, "", data, kind);
}

// A cube map of size^2 texels per face, faces in GL order and rows from j = 0 (the probes' data
// at binding 2): f(direction, face) at each texel centre.
template <class F>
std::vector<glm::vec4> cube_of(int size, F f) {
  std::vector<glm::vec4> texels;
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) texels.push_back(f(glsl::texel_direction(face, i, j, size), face));
  return texels;
}

}  // namespace nephele::test
