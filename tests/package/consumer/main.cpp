// C++ consumer: the <karma/...> include style.
#include <karma/MeGlobals.h>
#include <karma/Mst.h>
#include <karma/MeViewer.h>
#include <cstdio>

int main() {
  MeMatrix4 tm;
  MeMatrix4TMMakeIdentity(tm);
  MeMatrix4TMSetPosition(tm, 1, 2, 3);
  MeVector3 p;
  MeMatrix4TMGetPosition(p, tm);
  if (p[0] != 1 || p[1] != 2 || p[2] != 3) return 1;
  std::printf("karma consumer ok (C++, MeReal is %zu bytes)\n", sizeof(MeReal));
  return 0;
}
