#include "gpu/probe.hpp"

#include <cmath>
#include <stdexcept>

#include "gpu/compute_program.hpp"

namespace nephele::gpu {

std::string probe_source(const std::string& in_type, const std::string& out_type, const std::string& includes,
                         const std::string& helpers, const std::string& expression) {
  return "#version 450\n"
         "layout(local_size_x = 64) in;\n"
         "layout(std430, binding = " +
         std::to_string(probe_inputs_binding) + ") readonly buffer Inputs { " + in_type +
         " inputs[]; };\n"
         "layout(std430, binding = " +
         std::to_string(probe_outputs_binding) + ") writeonly buffer Outputs { " + out_type +
         " outputs[]; };\n"
         "uniform uint u_count;\n" +
         includes + "\n" + helpers + "\n" +
         "void main() {\n"
         "  uint k = gl_GlobalInvocationID.x;\n"
         "  if (k >= u_count) return;\n"
         "  " +
         in_type +
         " input_value = inputs[k];\n"
         "  outputs[k] = " +
         out_type + "(" + expression +
         ");\n"
         "}\n";
}

void run_probe(const std::string& source, const void* inputs, size_t input_bytes, void* outputs, size_t output_bytes,
               size_t count, const std::vector<glm::vec4>& data, ProbeData kind) {
  auto program = ComputeProgram::from_text("tests/probe.comp", source);
  GLuint buffers[2];
  glCreateBuffers(2, buffers);
  glNamedBufferStorage(buffers[0], static_cast<GLsizeiptr>(input_bytes), inputs, 0);
  glNamedBufferStorage(buffers[1], static_cast<GLsizeiptr>(output_bytes), nullptr, GL_MAP_READ_BIT);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, probe_inputs_binding, buffers[0]);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, probe_outputs_binding, buffers[1]);
  GLuint data_buffer = 0, data_image = 0;
  if (!data.empty() && kind == ProbeData::buffer) {
    glCreateBuffers(1, &data_buffer);
    glNamedBufferStorage(data_buffer, static_cast<GLsizeiptr>(data.size() * sizeof(glm::vec4)), data.data(), 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, probe_data_binding, data_buffer);
  } else if (!data.empty()) {
    const int size = static_cast<int>(std::lround(std::sqrt(static_cast<double>(data.size()) / 6.0)));
    if (static_cast<size_t>(6 * size * size) != data.size())
      throw std::invalid_argument("run_probe: image data of " + std::to_string(data.size()) +
                                  " texels is not six squares");
    glCreateTextures(kind == ProbeData::cube_image ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D_ARRAY, 1, &data_image);
    if (kind == ProbeData::cube_image)
      glTextureStorage2D(data_image, 1, GL_RGBA32F, size, size);
    else
      glTextureStorage3D(data_image, 1, GL_RGBA32F, size, size, 6);
    // Direct state access addresses a cube map's faces as the layers 0-5 (OpenGL 4.5, 8.6).
    glTextureSubImage3D(data_image, 0, 0, 0, 0, size, size, 6, GL_RGBA, GL_FLOAT, data.data());
    glBindImageTexture(probe_data_binding, data_image, 0, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
  }
  program.set("u_count", static_cast<unsigned>(count));
  program.dispatch_covering(static_cast<int>(count), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(buffers[1], 0, static_cast<GLsizeiptr>(output_bytes), outputs);
  glDeleteBuffers(2, buffers);
  if (data_buffer) glDeleteBuffers(1, &data_buffer);
  if (data_image) glDeleteTextures(1, &data_image);
}

}  // namespace nephele::gpu
