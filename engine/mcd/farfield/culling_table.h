// culling_table.h: symmetric tables of "do not pair" flags (the guide's
// McdCullingTable), internal to the axis-sort farfield.
//
// A table of size n holds n*n flags, always symmetric: setting [a][b] also
// sets [b][a]. Two proxies of one AxisSortSpace are culled (they act as a
// pairwise-disabled pair) when both carry culling parameters, both name the
// same table and the same culling ID, and the table's flag at their two
// culling indices is set. The space reads the flags each time it computes
// pair events. The guide calls changing a table while proxies refer to it
// undefined; here a change takes effect at the next McdSpaceEndChanges of
// every space (a pair that overlaps all along says goodbye when its flag is
// set and hello when it is cleared): CullingTableSet advances a revision
// shared by all tables, and a space that sees a new revision at EndChanges
// settles all its pairs instead of only the touched ones.
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

// A count advanced by every CullingTableSet that changes a flag of any table
// (thread-safe). Equal values read at two times mean no flag changed between.
std::uint64_t CullingTablesRevision();

}  // namespace karma::mcd

#endif
