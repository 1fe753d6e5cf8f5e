// Internal: a small fork-join pool for the learning kernels (EM passes, k-means passes).
#pragma once

#include <functional>

namespace tactile::analysis {

// Runs f(part) for every part in [0, parts) on up to `threads` threads (the calling thread is
// one of them) and returns when all are done. Parts are handed out dynamically, so callers must
// make each part's result independent of which thread ran it (write per-part outputs, reduce them
// in part order afterwards). The worker threads persist between calls. A call made while another
// call is using the pool, or from inside a part, runs its parts on the calling thread. A part that
// throws (on any thread) stops the handing out of parts; once every thread has left the job the
// first exception is thrown again on the calling thread.
void parallelFor(int parts, int threads, const std::function<void(int)>& f);

}  // namespace tactile::analysis
