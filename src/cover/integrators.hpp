#pragma once
// The warp's stepping rules and velocity sources as the host names them; the math is in
// shaders/lib/warp_step.glsl (shared with the C++ twin through shader_math.hpp).
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace nephele::cover {

// Values equal the INTEGRATOR_* numbers of warp_step.glsl.
enum class Integrator { euler = 0, heun = 1, rk4 = 2, geodesic = 3, adaptive = 4 };
// Where the warp takes the velocity: bilinearly from the curl cube map, the procedural curl
// evaluated at the exact point, or the cubic B-spline of the curl grid (curl_spline.glsl);
// automatic ("auto") is resolved before the passes by resolved_curl_mode (cover/global_cover.hpp).
enum class CurlMode { sampled, procedural, spline, automatic };

const char* integrator_name(Integrator integrator);
const char* curl_mode_name(CurlMode mode);
std::optional<Integrator> parse_integrator(const std::string& name);
std::optional<CurlMode> parse_curl_mode(const std::string& name);
const std::vector<Integrator>& all_integrators();
const std::vector<CurlMode>& all_curl_modes();  // the three a warp can run (not automatic)

// Order of convergence on a smooth flow (adaptive: that of the solution it advances with).
int integrator_order(Integrator integrator);
// Velocity evaluations per step (adaptive: per attempted step, first same as last).
int evaluations_per_step(Integrator integrator);

// Largest stable h L for a flow whose velocity gradient has eigenvalues of modulus at most L:
// the smaller of the scheme's stability intervals on the negative real axis (contracting
// strain) and the imaginary axis (rotation), where the scheme has one. Euler, geodesic Euler
// and Heun have none on the imaginary axis: they amplify rotation at every step size, by
// sqrt(1 + (hL)^2) and sqrt(1 + (hL)^4 / 4) per step, so their limit is the real-axis one, 2,
// and docs/numerics.md gives the growth. RK4: -2.785 on the real axis, 2.828 (2 sqrt 2) on the
// imaginary axis. Bogacki-Shampine 3: real axis 2.513, imaginary axis 1.732 (sqrt 3).
double stability_limit(Integrator integrator);

// Mesa's llvmpipe ends the loops of a shader invocation, silently, once all of them together
// have iterated 65535 times (LP_MAX_TGSI_LOOP_ITERATIONS in gallivm: one counter per
// invocation, shared by every loop). The warp pass therefore splits long integrations over
// several dispatches, each within half that budget (the other half is room for the rare
// 5 x 5 x 5 fallback search of Worley F1).
constexpr int shader_loop_budget = 32768;
// Loop iterations per step (adaptive: per attempted step) at most: the step loop itself and,
// per procedural evaluation, the octave loops of both potentials with the outer loops of the
// Worley cell search, 13 per octave and potential (measured on llvmpipe: about 50 for 3
// octaves; the bound is 78), and RK4's loop over its four stages. Sampled and spline
// evaluations have no loops.
int loop_iterations_per_step(Integrator integrator, CurlMode mode, int potential_octaves);
// Steps (adaptive: attempts) per texel that one dispatch of the warp pass may take.
int steps_per_dispatch(Integrator integrator, CurlMode mode, int potential_octaves);

// Preprocessor defines that select the variant of shaders/cover/warp.comp.
std::vector<std::pair<std::string, std::string>> warp_defines(Integrator integrator, CurlMode mode);

}  // namespace nephele::cover
