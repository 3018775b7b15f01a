// diagnostics.cpp: MeDiagnostics.h, the list of diagnostic sources.
#include "MeDiagnostics.h"

#include <algorithm>
#include <vector>

#include "MeMessage.h"

namespace {

struct Source {
  void *owner;
  MeDiagnosticRead read;
};

// Registration order; owners unique. Never destroyed, so a world destroyed
// during static destruction can still unregister.
std::vector<Source> &sources() {
  static std::vector<Source> *list = new std::vector<Source>;
  return *list;
}

}  // namespace

extern "C" {

void MEAPI MeDiagnosticSourceRegister(void *owner, MeDiagnosticRead read) {
  ME_REQUIRE_ARG(owner && read, "MeDiagnosticSourceRegister", "owner or reader is NULL");
  std::vector<Source> &list = sources();
  const auto listed = [&](const Source &s) { return s.owner == owner; };
  if (std::none_of(list.begin(), list.end(), listed)) list.push_back({owner, read});
}

void MEAPI MeDiagnosticSourceUnregister(void *owner) {
  std::vector<Source> &list = sources();
  list.erase(std::remove_if(list.begin(), list.end(), [&](const Source &s) { return s.owner == owner; }), list.end());
}

int MEAPI MeDiagnosticSourceCount(void) { return (int)sources().size(); }

MeBool MEAPI MeDiagnosticSourceRead(int i, MeDiagnosticFigures *figures) {
  ME_REQUIRE_ARG_RET(figures != nullptr, 0, "MeDiagnosticSourceRead", "figures is NULL");
  *figures = MeDiagnosticFigures{};
  const std::vector<Source> &list = sources();
  if (i < 0 || i >= (int)list.size()) return 0;
  list[(size_t)i].read(list[(size_t)i].owner, figures);
  return 1;
}

}  // extern "C"
