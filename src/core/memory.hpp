#pragma once
// How much host memory the commands may plan on, read once here for every size check.

namespace nephele::core {

// MemAvailable of /proc/meminfo in bytes (memory the kernel can hand out without swapping);
// 0 when unknown (no /proc, or a kernel without that line), in which case callers skip the check.
double host_memory_available_bytes();

}  // namespace nephele::core
