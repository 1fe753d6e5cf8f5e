// Progress reporting for long work in the core: the callback returns false to cancel.
#pragma once

#include <cstddef>
#include <functional>

namespace tactile {

// Called with (work done, total work) in whatever unit the caller documents; returning false asks
// the work to stop as soon as it safely can.
using ProgressFn = std::function<bool(std::size_t done, std::size_t total)>;

}  // namespace tactile
