#include "gpu/compute_program.hpp"

#include "gpu/shader_sources.hpp"

#include <cctype>

namespace nephele::gpu {
namespace {

bool is_identifier_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The identifiers of `text` (numbers' digits and suffixes are skipped with the number).
std::unordered_set<std::string> identifiers_of(const std::string& text) {
  std::unordered_set<std::string> names;
  for (std::size_t i = 0; i < text.size();) {
    if (is_identifier_start(text[i])) {
      const std::size_t start = i;
      while (i < text.size() && is_identifier_char(text[i])) ++i;
      names.emplace(text, start, i - start);
    } else if (std::isdigit(static_cast<unsigned char>(text[i]))) {
      while (i < text.size() && (is_identifier_char(text[i]) || text[i] == '.')) ++i;
    } else {
      ++i;
    }
  }
  return names;
}

}  // namespace

ComputeProgram::ComputeProgram(const std::string& path, const std::vector<std::pair<std::string, std::string>>& defines)
    : ComputeProgram(FromExpanded{}, path, expand_shader(path, defines)) {}

ComputeProgram ComputeProgram::from_text(const std::string& path, const std::string& text) {
  return ComputeProgram(FromExpanded{}, path, expand_shader_text(path, text));
}

ComputeProgram::ComputeProgram(FromExpanded, const std::string& path, const ExpandedShader& source)
    : path_(path), source_identifiers_(identifiers_of(source.text)) {
  const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
  const char* text = source.text.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(length > 0 ? length : 1), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    throw ShaderError("compiling " + path + " failed:\n" + name_files_in_log(log, source.files));
  }
  program_ = glCreateProgram();
  glAttachShader(program_, shader);
  glLinkProgram(program_);
  glDeleteShader(shader);
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(program_, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(length > 0 ? length : 1), '\0');
    glGetProgramInfoLog(program_, length, nullptr, log.data());
    glDeleteProgram(program_);
    throw ShaderError("linking " + path + " failed:\n" + name_files_in_log(log, source.files));
  }
  glGetProgramiv(program_, GL_COMPUTE_WORK_GROUP_SIZE, local_size_);
}

ComputeProgram::~ComputeProgram() {
  if (program_) glDeleteProgram(program_);
}

void ComputeProgram::use() const { glUseProgram(program_); }

bool ComputeProgram::has_uniform(const std::string& name) const {
  return glGetUniformLocation(program_, name.c_str()) >= 0;
}

GLint ComputeProgram::location(const std::string& name) const {
  const GLint where = glGetUniformLocation(program_, name.c_str());
  if (where >= 0) return where;
  // Inactive: fine when every identifier of the name ("u_march", "forward" of
  // "u_march.forward", "u_layers" and "base" of "u_layers[2].base") is in the source.
  for (std::size_t i = 0; i < name.size();) {
    if (!is_identifier_start(name[i])) {
      ++i;
      continue;
    }
    const std::size_t start = i;
    while (i < name.size() && is_identifier_char(name[i])) ++i;
    if (source_identifiers_.count(name.substr(start, i - start)) == 0)
      throw ShaderError(path_ + ": no uniform '" + name + "' in the shader");
  }
  return -1;  // glProgramUniform* ignores location -1
}

void ComputeProgram::set(const std::string& name, float value) const {
  glProgramUniform1f(program_, location(name), value);
}
void ComputeProgram::set(const std::string& name, int value) const {
  glProgramUniform1i(program_, location(name), value);
}
void ComputeProgram::set(const std::string& name, unsigned value) const {
  glProgramUniform1ui(program_, location(name), value);
}
void ComputeProgram::set(const std::string& name, glm::vec2 value) const {
  glProgramUniform2f(program_, location(name), value.x, value.y);
}
void ComputeProgram::set(const std::string& name, glm::vec3 value) const {
  glProgramUniform3f(program_, location(name), value.x, value.y, value.z);
}
void ComputeProgram::set(const std::string& name, glm::vec4 value) const {
  glProgramUniform4f(program_, location(name), value.x, value.y, value.z, value.w);
}
void ComputeProgram::set(const std::string& name, glm::ivec2 value) const {
  glProgramUniform2i(program_, location(name), value.x, value.y);
}

void ComputeProgram::set(const std::string& name, glm::ivec3 value) const {
  glProgramUniform3i(program_, location(name), value.x, value.y, value.z);
}

void ComputeProgram::dispatch_covering(int width, int height, int depth) const {
  use();
  auto groups = [](int n, int local) { return static_cast<GLuint>((n + local - 1) / local); };
  glDispatchCompute(groups(width, local_size_[0]), groups(height, local_size_[1]), groups(depth, local_size_[2]));
}

}  // namespace nephele::gpu
