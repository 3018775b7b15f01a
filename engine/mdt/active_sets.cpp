// active_sets.cpp: the awake list, the driven list and the body lists of
// constraints (invariants in active_sets.h).
#include "active_sets.h"

namespace karma::mdt {

void addAwake(MdtWorldPrivate *p, MdtBody *b) {
  b->awakeSlot = (int)p->active->awake.size();
  p->active->awake.push_back(b);
}

void removeAwake(MdtWorldPrivate *p, MdtBody *b) {
  std::vector<MdtBody *> &awake = p->active->awake;
  const int slot = b->awakeSlot;
  if (slot < 0 || slot >= (int)awake.size() || awake[(size_t)slot] != b) return;
  MdtBody *last = awake.back();
  awake[(size_t)slot] = last;
  last->awakeSlot = slot;
  awake.pop_back();
  b->awakeSlot = -1;
}

void noteDriven(MdtBody *b) {
  if (b->enabled || b->drivenListed) return;
  b->drivenListed = TRUE;
  b->world->priv->active->driven.push_back(b);
}

namespace {

void unlinkSide(MdtConstraint *c, int k) {
  MdtBody *b = c->linked[k];
  if (!b) return;
  MdtConstraint *prev = c->linkPrev[k], *next = c->linkNext[k];
  if (prev)
    prev->linkNext[prev->linked[0] == b ? 0 : 1] = next;
  else
    b->firstConstraint = next;
  if (next) next->linkPrev[next->linked[0] == b ? 0 : 1] = prev;
  c->linked[k] = nullptr;
  c->linkPrev[k] = c->linkNext[k] = nullptr;
}

void linkSide(MdtConstraint *c, int k, MdtBody *b) {
  c->linked[k] = b;
  c->linkPrev[k] = nullptr;
  c->linkNext[k] = b->firstConstraint;
  if (MdtConstraint *head = b->firstConstraint) head->linkPrev[head->linked[0] == b ? 0 : 1] = c;
  b->firstConstraint = c;
}

}  // namespace

void linkConstraint(MdtConstraint *c) {
  if (c->linked[0] == c->body[0] && c->linked[1] == c->body[1]) return;
  unlinkConstraint(c);
  for (int k = 0; k < 2; ++k)
    if (c->body[k]) linkSide(c, k, c->body[k]);
}

void unlinkConstraint(MdtConstraint *c) {
  for (int k = 0; k < 2; ++k) unlinkSide(c, k);
}

}  // namespace karma::mdt
