#include "shader_math/uniforms.hpp"

namespace nephele::glsl {
namespace {

template <class T>
void set_member(const gpu::ComputeProgram& program, const std::string& name, T value, Members members) {
  if (members == Members::all || program.has_uniform(name)) program.set(name, value);
}

}  // namespace

void set_uniform(const gpu::ComputeProgram& program, const std::string& name, const FbmParams& params,
                 Members members) {
  set_member(program, name + ".frequency", params.frequency, members);
  set_member(program, name + ".octaves", params.octaves, members);
  set_member(program, name + ".lacunarity", params.lacunarity, members);
  set_member(program, name + ".gain", params.gain, members);
  set_member(program, name + ".seed", static_cast<unsigned>(params.seed), members);
  set_member(program, name + ".period", params.period, Members::active);
}

void set_uniform(const gpu::ComputeProgram& program, const std::string& name, const CurlParams& params) {
  set_uniform(program, name + ".potential_north", params.potential_north);
  set_uniform(program, name + ".potential_south", params.potential_south);
  program.set(name + ".prevailing", params.prevailing);
  program.set(name + ".mix_frequency", params.mix_frequency);
  program.set(name + ".strength", params.strength);
}

}  // namespace nephele::glsl
