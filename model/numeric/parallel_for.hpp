// Runs independent jobs 0..count−1 on a few threads (multi-start fits, bootstrap refits, synthetic
// trials). Jobs are handed out one at a time, so uneven jobs balance; an exception from any job is
// rethrown on the calling thread after every worker has joined (the first by job index).
#pragma once

#include <cstddef>
#include <functional>

namespace nibrig::model::numeric {

// threads = 0: one per core. Each job must write only its own results.
void parallel_for(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& job);

}  // namespace nibrig::model::numeric
