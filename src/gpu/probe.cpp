#include "gpu/probe.hpp"

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
               size_t count, const std::vector<glm::vec4>& data) {
  auto program = ComputeProgram::from_text("tests/probe.comp", source);
  GLuint buffers[2];
  glCreateBuffers(2, buffers);
  glNamedBufferStorage(buffers[0], static_cast<GLsizeiptr>(input_bytes), inputs, 0);
  glNamedBufferStorage(buffers[1], static_cast<GLsizeiptr>(output_bytes), nullptr, GL_MAP_READ_BIT);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, probe_inputs_binding, buffers[0]);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, probe_outputs_binding, buffers[1]);
  GLuint data_buffer = 0;
  if (!data.empty()) {
    glCreateBuffers(1, &data_buffer);
    glNamedBufferStorage(data_buffer, static_cast<GLsizeiptr>(data.size() * sizeof(glm::vec4)), data.data(), 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, probe_data_binding, data_buffer);
  }
  program.set("u_count", static_cast<unsigned>(count));
  program.dispatch_covering(static_cast<int>(count), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(buffers[1], 0, static_cast<GLsizeiptr>(output_bytes), outputs);
  glDeleteBuffers(2, buffers);
  if (data_buffer) glDeleteBuffers(1, &data_buffer);
}

}  // namespace nephele::gpu
