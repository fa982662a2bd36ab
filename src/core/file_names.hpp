#pragma once
// File names as users type them: extensions compare without regard to case (a.PNG is a PNG),
// the same for every command.
#include <filesystem>
#include <string>

namespace nephele::core {

// The extension of `path` with its dot, in lower case ASCII: ".png" for "x.PNG", "" for none.
std::string lowercase_extension(const std::filesystem::path& path);

}  // namespace nephele::core
