#pragma once
// PNG encoding through libpng itself, not through OpenImageIO's module (image_codecs.hpp): the
// renders write nothing but PNGs, and loading OpenImageIO's 250 libraries for them cost more CPU
// than the encoding (docs/performance.md, "Process start"). image_files.cpp's encode_image and
// ImageRowWriter use it for every PNG, so that each image has one encoder.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>

#include "files/image_files.hpp"

namespace nephele::files {

class PngEncoder {
 public:
  // Where the encoded bytes go: returns 0, or the errno of a failed write.
  using Sink = std::function<int(const unsigned char* bytes, std::size_t size)>;
  // An image of width x height pixels of 1-4 channels (grey, grey and alpha, RGB, RGBA) as
  // `encoding` says (checked by the caller: 8 or 16 bits). Throws std::runtime_error naming `what`.
  PngEncoder(Sink sink, int width, int height, int channels, const ImageEncoding& encoding, const std::string& what);
  ~PngEncoder();
  PngEncoder(const PngEncoder&) = delete;
  PngEncoder& operator=(const PngEncoder&) = delete;
  // `rows` rows of width x channels floats from the next row on, each value v stored as
  // round((2^bits - 1) clamp(v, 0, 1)) (NaN as 0).
  void write_rows(int rows, const float* pixels);
  // After the last row: the image's end.
  void finish();

  struct State;  // libpng's structures and the row being encoded (png_encoder.cpp)

 private:
  std::unique_ptr<State> state_;
};

}  // namespace nephele::files
