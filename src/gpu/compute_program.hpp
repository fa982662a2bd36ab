#pragma once
// A compute shader program built from the embedded shader library.
#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "gpu/shader_sources.hpp"

#include <stdexcept>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

namespace nephele::gpu {

class ShaderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ComputeProgram {
 public:
  // `path` is relative to shaders/, e.g. "cover/curl.comp". Compile errors name the file and line.
  explicit ComputeProgram(const std::string& path,
                          const std::vector<std::pair<std::string, std::string>>& defines = {});
  // A program from source text under a virtual path (test probes); includes resolve against
  // the embedded library.
  static ComputeProgram from_text(const std::string& path, const std::string& text);
  ~ComputeProgram();
  ComputeProgram(const ComputeProgram&) = delete;
  ComputeProgram& operator=(const ComputeProgram&) = delete;

  void use() const;
  // Setting a uniform that the shader does not declare is an error: host and shader disagree.
  // A declared uniform that the compiler removed as unused is set as GL sets location -1: not
  // at all. Drivers differ in what they remove (NVIDIA drops unused members of a uniform struct,
  // Mesa keeps them), so the check is against the source's names, not the active list.
  void set(const std::string& name, float value) const;
  void set(const std::string& name, int value) const;
  void set(const std::string& name, unsigned value) const;
  void set(const std::string& name, glm::vec2 value) const;
  void set(const std::string& name, glm::vec3 value) const;
  void set(const std::string& name, glm::vec4 value) const;
  void set(const std::string& name, glm::ivec2 value) const;
  void set(const std::string& name, glm::ivec3 value) const;
  bool has_uniform(const std::string& name) const;  // active in the linked program
  // Dispatches enough groups of the shader's local size to cover width x height x depth.
  void dispatch_covering(int width, int height, int depth) const;
  GLuint id() const { return program_; }

 private:
  struct FromExpanded {};
  ComputeProgram(FromExpanded, const std::string& path, const ExpandedShader& source);
  GLint location(const std::string& name) const;
  std::string path_;
  std::unordered_set<std::string> source_identifiers_;  // every identifier of the expanded source
  GLuint program_ = 0;
  GLint local_size_[3] = {1, 1, 1};
};

}  // namespace nephele::gpu
