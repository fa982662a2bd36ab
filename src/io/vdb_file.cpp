// Without OpenVDB: no .vdb (the build with it replaces this file's functions; docs/model.md).
#include "io/model_files.hpp"

namespace nephele::io {

bool vdb_available() { return false; }
std::string vdb_bytes(const model::CloudModel&, int, const std::vector<float>&) { return {}; }

}  // namespace nephele::io
