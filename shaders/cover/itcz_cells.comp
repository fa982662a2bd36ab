#version 450
// Pass 4a's first step: the ITCZ's cells for the frame (weather_systems.glsl's itcz_cell), every
// cell of its two lattices that a texel's search can reach, for the cloud layer of `u_seed`, into
// the tables the density pass reads (cover_density.comp's TABLED_CONVECTIVE_CELL): entry e of
// layer k of u_layers at e u_layers + k. The same function of the cell as where the density would
// compute it, once per cell instead of at each of the texels around it.
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
#include "../lib/weather_systems.glsl"

layout(std430, binding = 9) writeonly buffer ItczCells { vec4 itcz_cells[]; };
uniform WeatherSystems u_systems;
uniform uint u_seed;
uniform int u_layers;  // the cloud layers the tables hold: 1 (steady flow) or 2 (moving)
uniform int u_layer;   // this one's

void main() {
  int index = int(gl_GlobalInvocationID.x);
  if (index >= ITCZ_TABLE_CELLS) return;
  ivec4 cell = itcz_table_cell(index);
  itcz_cells[index * u_layers + u_layer] =
      itcz_cell(cell.w, cell.xyz, u_systems.itcz_latitude, u_systems.itcz_waves, u_seed);
}
