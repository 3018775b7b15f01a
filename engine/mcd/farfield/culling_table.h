// culling_table.h: symmetric tables of "do not pair" flags (the guide's
// McdCullingTable), internal to the axis-sort farfield.
//
// A table of size n holds n*n flags, always symmetric: setting [a][b] also
// sets [b][a]. Two proxies of one AxisSortSpace are culled (they act as a
// pairwise-disabled pair) when both carry culling parameters, both name the
// same table and the same culling ID, and the table's flag at their two
// culling indices is set. The space reads the flags each time it computes
// pair events, so a table must stay unchanged while proxies refer to it
// (the guide calls changing it then undefined; here it takes effect at the
// next McdSpaceEndChanges, which is a defined result).
//
// Public C mapping: McdCullingTableCreate(size) -> CullingTableCreate,
// McdCullingTableSet(t, a, b, flag) -> CullingTableSet (returns t),
// McdCullingTableDestroy -> CullingTableDestroy. The public McdCullingTable
// can simply be this struct.
#ifndef KARMA_MCD_FARFIELD_CULLING_TABLE_H
#define KARMA_MCD_FARFIELD_CULLING_TABLE_H

#include "MePrecision.h"

#include <cstdint>

namespace karma::mcd {

struct CullingTable {
  int size = 0;                   // indices run over [0, size)
  std::uint8_t *flags = nullptr;  // size*size bytes, row major, symmetric
};

// A table of `size` cleared flags (size >= 1), allocated through MeMemoryAPI.
// Returns NULL with an MeWarning naming McdCullingTableCreate on a bad size
// or when memory runs out.
CullingTable *CullingTableCreate(int size);

// Releases a table; NULL is ignored. Proxies must no longer refer to it.
void CullingTableDestroy(CullingTable *table);

// Sets flags [a][b] and [b][a] to `flag` (non-zero = cull). An index outside
// [0, size) warns (naming McdCullingTableSet) and changes nothing. Returns
// `table`, as the guide's McdCullingTableSet does.
CullingTable *CullingTableSet(CullingTable *table, std::uint32_t a, std::uint32_t b, MeBool flag);

// The flag at [a][b]; false for a NULL table or an index out of range.
bool CullingTableGet(const CullingTable *table, std::uint32_t a, std::uint32_t b);

}  // namespace karma::mcd

#endif
