// culling_table.cpp: the symmetric flag tables of culling_table.h.
// Invariants: flags[a*size + b] == flags[b*size + a] for every a, b;
// gRevision advances whenever any table's flags change.
#include "culling_table.h"

#include "MeMemory.h"
#include "MeMessage.h"

#include <atomic>
#include <new>

namespace karma::mcd {

namespace {
std::atomic<std::uint64_t> gRevision{0};
}  // namespace

std::uint64_t CullingTablesRevision() { return gRevision.load(); }

CullingTable *CullingTableCreate(int size) {
  // size*size flags must fit a size_t and stay reasonable; 65535 is ~4 GiB.
  if (size < 1 || size > 65535) {
    MeWarning(0, "McdCullingTableCreate: size %d must be between 1 and 65535; no table created", size);
    return nullptr;
  }
  void *mem = MeMemoryAPI.create(sizeof(CullingTable));
  if (!mem) return nullptr;
  auto *table = new (mem) CullingTable{};
  const std::size_t count = static_cast<std::size_t>(size) * static_cast<std::size_t>(size);
  table->flags = static_cast<std::uint8_t *>(MeMemoryAPI.createZeroed(count));
  if (!table->flags) {
    MeMemoryAPI.destroy(table);
    return nullptr;
  }
  table->size = size;
  return table;
}

void CullingTableDestroy(CullingTable *table) {
  if (!table) return;
  MeMemoryAPI.destroy(table->flags);
  table->~CullingTable();
  MeMemoryAPI.destroy(table);
}

CullingTable *CullingTableSet(CullingTable *table, std::uint32_t a, std::uint32_t b, MeBool flag) {
  if (!table) {
    MeWarning(0, "McdCullingTableSet: table is NULL");
    return table;
  }
  const auto n = static_cast<std::uint32_t>(table->size);
  if (a >= n || b >= n) {
    MeWarning(0, "McdCullingTableSet: index (%u, %u) outside the table of size %d; nothing set", a, b, table->size);
    return table;
  }
  const std::uint8_t v = flag ? 1 : 0;
  if (table->flags[static_cast<std::size_t>(a) * n + b] == v) return table;
  table->flags[static_cast<std::size_t>(a) * n + b] = v;
  table->flags[static_cast<std::size_t>(b) * n + a] = v;
  ++gRevision;
  return table;
}

bool CullingTableGet(const CullingTable *table, std::uint32_t a, std::uint32_t b) {
  if (!table) return false;
  const auto n = static_cast<std::uint32_t>(table->size);
  if (a >= n || b >= n) return false;
  return table->flags[static_cast<std::size_t>(a) * n + b] != 0;
}

}  // namespace karma::mcd
