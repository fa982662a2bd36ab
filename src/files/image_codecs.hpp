#pragma once
// The image codecs behind image_files.hpp: OpenImageIO in a module of its own,
// nephele_image_codecs.so (files/codecs/), loaded on first use. OpenImageIO brings some 250
// shared libraries (OpenCV, FFmpeg, GDAL, ...) whose loading took 0.4 s of every nephele
// process's start, also of those that never touch an image file (docs/performance.md,
// "Process start"). The module fills one table of functions; image_files.cpp checks the
// arguments, owns the files and calls the table. Nothing but that file and the module includes
// this header.
#include <string>
#include <vector>

#include "files/image_files.hpp"

namespace nephele::files {

// A module's table carries this version; a module of another version is refused.
inline constexpr int image_codecs_version = 1;
// The one symbol the module exports: `extern "C" const ImageCodecs* nephele_image_codecs()`.
inline constexpr const char* image_codecs_entry = "nephele_image_codecs";
// The module's file name.
inline constexpr const char* image_codecs_file = "nephele_image_codecs.so";

struct ImageWriterHandle;  // the module's row writer (an OpenImageIO ImageOutput), opaque here
struct ImageReaderHandle;  // the module's reader (an OpenImageIO ImageInput)

// The functions throw std::runtime_error naming `what` or the path, as image_files.hpp's do. The
// arguments are checked by image_files.cpp before they come here (check_encoding). The writers
// write EXR: PNGs are libpng's (files/png_encoder.hpp).
struct ImageCodecs {
  int version;
  std::vector<unsigned char> (*encode_image)(const ImageData& image, const ImageEncoding& encoding,
                                             const std::string& what);
  std::vector<unsigned char> (*encode_animation)(const std::vector<ImageData>& frames, int frames_per_second,
                                                 const std::string& what);
  // Writes into the open file descriptor `fd`, which stays the caller's (it syncs and closes it).
  ImageWriterHandle* (*open_writer)(int fd, const std::string& what, int width, int height, int channels,
                                    const ImageEncoding& encoding);
  void (*write_rows)(ImageWriterHandle* writer, int first_row, int rows, const float* pixels);
  void (*finish_writer)(ImageWriterHandle* writer);  // writes the file's end; throws if any write failed
  void (*free_writer)(ImageWriterHandle* writer);    // also of a writer not finished
  // Opens a regular file (the caller checked) and fills `header`.
  ImageReaderHandle* (*open_reader)(const std::string& path, ImageHeader& header);
  void (*read_rows)(ImageReaderHandle* reader, int first_row, int rows, float* out);
  void (*read_all)(ImageReaderHandle* reader, float* out);  // every pixel, as floats
  void (*free_reader)(ImageReaderHandle* reader);
  // draw_text with the font file `font` (image_files.hpp).
  bool (*draw_text)(ImageData& image, int x, int y, const std::string& text, int size, const float rgb[3],
                    const char* font);
};

// The module's table, loaded on the first call (or waiting for preload_image_codecs' load).
// Throws std::runtime_error naming where the module was looked for and why it did not load:
// $NEPHELE_IMAGE_CODECS if set, else beside the executable, else where the build put it.
const ImageCodecs& image_codecs();

}  // namespace nephele::files
