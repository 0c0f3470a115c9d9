#pragma once
// LoopState (model/loop_state.hpp) as named arrays of doubles and integers, bit for bit, for
// checkpoints (io/checkpoint.hpp): every field, vectors as they are, scalars in small arrays.
#include "model/loop_state.hpp"
#include "model/run_observer.hpp"

namespace slidewave {

StateArrays to_arrays(const LoopState& loop);

/// Overwrites `loop` (already sized by the setup of the same model) with the arrays. Throws
/// std::runtime_error naming the array that is missing or has another size than the setup's.
void restore_from_arrays(const StateArrays& arrays, LoopState& loop);

}  // namespace slidewave
