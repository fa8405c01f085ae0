#include "process/malloc_arenas.hpp"

#include <malloc.h>

namespace fosls {

bool use_one_malloc_arena() { return mallopt(M_ARENA_MAX, 1) == 1; }

}  // namespace fosls
