// MemoryApi.cpp: the global allocator table and its reset.
#include "MemoryDefaults.h"

extern "C" {

// Constant-initialised, so allocations made during static initialisation
// (in any translation unit) already find the defaults.
MEPUBLIC constinit MeMemoryAPIStruct MeMemoryAPI = karma::me::defaultMemoryAPI;

MEPUBLIC void MEAPI MeMemoryAPIReset(void) { MeMemoryAPI = karma::me::defaultMemoryAPI; }

}  // extern "C"
