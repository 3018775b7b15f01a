// capping.cpp: matrix capping (the guide's Appendix C and Q&A).
//
// When a partition has more rows than the world's maxMatrixSize, rows are
// dropped until it fits, in this order:
//   1. friction rows of every contact;
//   2. normal rows of contacts between two bodies;
//   3. normal rows of contacts with the world.
// Within each class, contacts go least important first: shallowest
// penetration first, or lowest value of the world's importance callback.
// Joint, limit and motor rows are never dropped, and each contact group (a
// stand-alone contact is a group of one) keeps at least its most important
// contact. Ties keep the rows' solve order, so capping is deterministic.
#include <algorithm>

#include "step.h"

namespace karma::mdt {

namespace {

struct Candidate {
  int row;
  int cls;        // 1 friction, 2 body-body normal, 3 body-world normal
  MeReal weight;  // importance: lower goes first
  MdtConstraint *group;
};

MdtConstraint *groupOf(MdtConstraint *contact) { return contact->owner ? contact->owner : contact; }

}  // namespace

void capRows(MdtWorldID world, std::span<const Row> rows, std::span<char> keep, int maxRows) {
  const int rowCount = (int)rows.size();
  MdtContactImportanceCBPtr importance = world->priv->importance;
  std::vector<Candidate> cand;
  for (int r = 0; r < rowCount; ++r) {
    const Row &row = rows[(size_t)r];
    if (row.role != RowRole::ContactNormal && row.role != RowRole::ContactFriction) continue;
    if (!row.contact) continue;
    Candidate c;
    c.row = r;
    c.group = groupOf(row.contact);
    c.weight = importance ? importance(reinterpret_cast<MdtContact *>(row.contact)) : row.depth;
    if (row.role == RowRole::ContactFriction)
      c.cls = 1;
    else
      c.cls = row.contact->body[1] ? 2 : 3;
    cand.push_back(c);
  }
  std::stable_sort(cand.begin(), cand.end(), [](const Candidate &a, const Candidate &b) {
    if (a.cls != b.cls) return a.cls < b.cls;
    return a.weight < b.weight;
  });
  // Normal rows still kept per group, so the last one survives.
  std::vector<std::pair<MdtConstraint *, int>> normals;
  auto normalsOf = [&normals](MdtConstraint *g) -> int & {
    for (auto &e : normals)
      if (e.first == g) return e.second;
    normals.emplace_back(g, 0);
    return normals.back().second;
  };
  for (const Candidate &c : cand)
    if (c.cls != 1) ++normalsOf(c.group);

  int kept = rowCount;
  for (const Candidate &c : cand) {
    if (kept <= maxRows) break;
    if (c.cls != 1) {
      int &left = normalsOf(c.group);
      if (left <= 1) continue;
      --left;
      // Its friction rows (if any survived) go with it.
      const MdtConstraint *contact = rows[(size_t)c.row].contact;
      for (int r = 0; r < rowCount; ++r) {
        const Row &row = rows[(size_t)r];
        if (row.contact == contact && row.role == RowRole::ContactFriction && keep[(size_t)r]) {
          keep[(size_t)r] = 0;
          --kept;
        }
      }
    }
    keep[(size_t)c.row] = 0;
    --kept;
  }
}

}  // namespace karma::mdt
