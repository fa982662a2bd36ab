#pragma once
// Block compression of one image into the BCn formats that GPUs sample directly (BC1, BC3, BC4;
// Khronos Data Format Specification 1.3, "S3TC" and "RGTC" sections), encoded by NVIDIA Texture
// Tools 2 (Debian's libnvtt). docs/export.md lists which target reads which format.
#include <cstddef>
#include <vector>

namespace nephele::files {

// bc1: RGB in 4x4 blocks of 8 bytes (opaque, 4-colour mode); bc3: BC1 colour + an 8-byte
// interpolated alpha block; bc4: one channel (red) in blocks of 8 bytes.
enum class BlockFormat { bc1, bc3, bc4 };

int block_bytes(BlockFormat format);     // 8, 16, 8
int block_channels(BlockFormat format);  // 4 (RGBA input), 4, 1
// ceil(width / 4) ceil(height / 4) blocks: images smaller than a block are padded (KTX2 and DDS
// store partial blocks whole).
std::size_t compressed_image_bytes(int width, int height, BlockFormat format);

// The blocks of one width x height image, row-major from the top row, blocks in row-major order.
// `texels` holds block_channels(format) floats per texel in [0, 1] (RGBA for bc1 and bc3, whose
// alpha bc1 ignores); each is first rounded to 8 bits, the precision of the formats' endpoints.
// Encoded by libnvtt: BC4 at its production quality, BC1 and BC3 at its fastest (see the .cpp).
std::vector<unsigned char> compress_image(const float* texels, int width, int height, BlockFormat format);

}  // namespace nephele::files
