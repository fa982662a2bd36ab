#pragma once
// The one upload of the library's parameter blocks (FbmParams, CurlParams, FlowMotion, WeatherSystems, MarchParams) to
// a shader's uniform struct of the same layout.
#include <string>

#include "gpu/compute_program.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::glsl {

// Which members of a block the program must have.
enum class Members {
  all,     // every one: a member the linker removed means host and shader disagree
  active,  // those the linker kept (shader variants that read only part of a block)
};

// Uploads `params` to the uniform struct `name`. fBm's period is set only where the program
// reads it, also with Members::all: noise on the sphere is not periodic.
void set_uniform(const gpu::ComputeProgram& program, const std::string& name, const FbmParams& params,
                 Members members = Members::all);
void set_uniform(const gpu::ComputeProgram& program, const std::string& name, const CurlParams& params);
void set_uniform(const gpu::ComputeProgram& program, const std::string& name, const FlowMotion& motion);
// Every member, all MAX_CYCLONES cyclones included (those past cyclone_count as given).
void set_uniform(const gpu::ComputeProgram& program, const std::string& name, const WeatherSystems& systems);
// Every member, all MAX_LAYERS layers included (those past layer_count as given).
void set_uniform(const gpu::ComputeProgram& program, const std::string& name, const MarchParams& params);

}  // namespace nephele::glsl
