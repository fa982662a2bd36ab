#pragma once
// Image files through OpenImageIO. Coverage is data, not colour: nothing is sRGB-encoded.
#include <filesystem>
#include <string>
#include <vector>

#include "core/image.hpp"

namespace nephele::io {

using core::ImageData;

// Float EXR (zip-compressed) with the given channel names; `format_path` picks the writer by
// extension when `path` is a temporary name.
void write_float_image(const std::filesystem::path& path, const ImageData& image,
                       const std::vector<std::string>& channel_names,
                       const std::string& format_path = "");
// 8-bit PNG of values in [0, 1], quantised linearly (round(255 v)), no gamma or sRGB chunk.
void write_png8(const std::filesystem::path& path, const ImageData& image,
                const std::string& format_path = "");
ImageData read_image(const std::filesystem::path& path);

}  // namespace nephele::io
