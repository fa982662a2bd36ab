#pragma once
// Work on rows shared by the machine's hardware threads: the CPU resamplers of covers too large
// for the GPU (cover/streamed_equirect.cpp, the exr-cube export) and the regional weather field
// sampled from a cover (regional/weather_field.cpp).
#include <algorithm>
#include <functional>
#include <thread>
#include <vector>

namespace nephele::core {

// Calls work(begin, end) on contiguous shares of [0, count), one per thread (at most 16), and
// returns when all are done. The shares do not depend on the timing, so the results are the
// same whatever the threads' order as long as work writes only its own rows.
inline void parallel_rows(int count, const std::function<void(int begin, int end)>& work) {
  const int threads = static_cast<int>(std::max(1u, std::min(16u, std::thread::hardware_concurrency())));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, t * count / threads, (t + 1) * count / threads);
  work(0, count / threads);
  for (std::thread& thread : pool) thread.join();
}

}  // namespace nephele::core
