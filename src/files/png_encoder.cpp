#include "files/png_encoder.hpp"

#include <png.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace nephele::files {

struct PngEncoder::State {
  Sink sink;
  std::string what;
  png_structp png = nullptr;
  png_infop info = nullptr;
  char message[256] = {};  // libpng's error, kept in plain memory: it is set just before a longjmp
  int sink_error = 0;
  int width = 0, height = 0, channels = 0, bits = 8, next_row = 0;
  bool divide_by_alpha = false;
  std::vector<std::string> text;  // key, value, key, value ... for the tEXt chunks
  std::vector<unsigned char> row;
  // Also when the encoder's constructor throws after libpng started.
  ~State() {
    if (png != nullptr) png_destroy_write_struct(&png, info != nullptr ? &info : nullptr);
  }
};

namespace {

using State = PngEncoder::State;

[[noreturn]] void on_error(png_structp png, png_const_charp message) {
  auto* state = static_cast<State*>(png_get_error_ptr(png));
  std::snprintf(state->message, sizeof state->message, "%s", message ? message : "libpng error");
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

void on_write(png_structp png, png_bytep data, size_t length) {
  auto* state = static_cast<State*>(png_get_io_ptr(png));
  int error = 0;
  try {
    error = state->sink(data, length);
  } catch (...) {
    error = ENOMEM;
  }
  if (error != 0) {
    state->sink_error = error;
    png_error(png, "the write failed");
  }
}

void on_flush(png_structp) {}

// Runs `call` (libpng calls only: libpng's errors leave it by longjmp, past any destructor) and
// says whether libpng reported no error.
template <class Call>
bool png_guarded(png_structp png, Call&& call) {
  if (setjmp(png_jmpbuf(png))) return false;
  call();
  return true;
}

[[noreturn]] void fail(const State& state, const char* step) {
  if (state.sink_error != 0)
    throw std::runtime_error("could not write " + state.what + ": " + std::strerror(state.sink_error));
  throw std::runtime_error("could not " + std::string(step) + " " + state.what + ": " + state.message);
}

}  // namespace

PngEncoder::PngEncoder(Sink sink, int width, int height, int channels, const ImageEncoding& encoding,
                       const std::string& what)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.sink = std::move(sink);
  s.what = what;
  s.width = width;
  s.height = height;
  s.channels = channels;
  s.bits = encoding.bits;
  // PNG's alpha is unassociated: a colour given premultiplied is divided by its alpha.
  s.divide_by_alpha = channels == 4 && !encoding.unassociated_alpha;
  if (width < 1 || height < 1 || channels < 1 || channels > 4)
    throw std::invalid_argument(what + ": a PNG of " + std::to_string(width) + " x " + std::to_string(height) + " x " +
                                std::to_string(channels) + " (1 to 4 channels)");
  s.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &s, on_error, on_warning);
  if (s.png == nullptr) throw std::runtime_error("could not encode " + what + ": libpng could not start");
  s.info = png_create_info_struct(s.png);
  if (s.info == nullptr) throw std::runtime_error("could not encode " + what + ": libpng could not start");
  s.text = {"Software", "nephele"};
  for (const auto& [name, value] : encoding.attributes) {
    s.text.push_back(name);
    s.text.push_back(value);
  }
  std::vector<png_text> chunks(s.text.size() / 2);
  for (size_t k = 0; k < chunks.size(); ++k) {
    chunks[k] = png_text{};
    chunks[k].compression = PNG_TEXT_COMPRESSION_NONE;
    chunks[k].key = s.text[2 * k].data();
    chunks[k].text = s.text[2 * k + 1].data();
  }
  const int colour_types[4] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                               PNG_COLOR_TYPE_RGB_ALPHA};
  const int level = std::clamp(encoding.png_compression_level, 0, 9), filters = encoding.png_filters;
  png_structp png = s.png;
  png_infop info = s.info;
  png_text* text = chunks.data();
  const int count = static_cast<int>(chunks.size());
  if (!png_guarded(png, [&] {
        png_set_write_fn(png, &s, on_write, on_flush);
        png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), s.bits, colour_types[channels - 1],
                     PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        png_set_compression_level(png, level);
        if (filters != 0) png_set_filter(png, PNG_FILTER_TYPE_BASE, filters);
        png_set_text(png, info, text, count);
        png_write_info(png, info);
      }))
    fail(s, "encode");
  s.row.resize(std::size_t(width) * channels * (s.bits / 8));
}

PngEncoder::~PngEncoder() = default;

void PngEncoder::write_rows(int rows, const float* pixels) {
  State& s = *state_;
  if (rows < 0 || s.next_row + rows > s.height)
    throw std::logic_error("PngEncoder: more rows than the image's " + std::to_string(s.height));
  const float top = s.bits == 16 ? 65535.0f : 255.0f;
  const int channels = s.channels;
  const std::size_t values = std::size_t(s.width) * channels;
  for (int r = 0; r < rows; ++r) {
    const float* in = pixels + std::size_t(r) * values;
    unsigned char* out = s.row.data();
    for (std::size_t k = 0; k < values; ++k) {
      float v = in[k];
      if (s.divide_by_alpha && k % 4 != 3) {
        const float alpha = in[k - k % 4 + 3];
        if (alpha > 0.0f) v /= alpha;
      }
      v = v > 0.0f ? std::min(v, 1.0f) : 0.0f;  // NaN to 0 as well
      const auto q = static_cast<unsigned>(std::floor(v * top + 0.5f));
      if (s.bits == 16) {
        out[2 * k] = static_cast<unsigned char>(q >> 8);  // PNG's samples are big-endian
        out[2 * k + 1] = static_cast<unsigned char>(q & 0xFF);
      } else {
        out[k] = static_cast<unsigned char>(q);
      }
    }
    png_structp png = s.png;
    png_bytep row = s.row.data();
    if (!png_guarded(png, [&] { png_write_row(png, row); })) fail(s, "encode");
    ++s.next_row;
  }
}

void PngEncoder::finish() {
  State& s = *state_;
  if (s.next_row != s.height)
    throw std::logic_error("PngEncoder: " + std::to_string(s.next_row) + " of " + std::to_string(s.height) +
                           " rows written to " + s.what);
  png_structp png = s.png;
  if (!png_guarded(png, [&] { png_write_end(png, nullptr); })) fail(s, "encode");
}

}  // namespace nephele::files
