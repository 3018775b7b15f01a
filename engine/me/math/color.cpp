// color.cpp: HSV -> RGB on the hexcone.
//
// The hue circle is cut into six 60-degree sectors; in sector i, with
// fraction f through it and chroma spread p = v(1-s), q = v(1-sf),
// t = v(1-s(1-f)), the colour is
//   i: 0 (v,t,p)  1 (q,v,p)  2 (p,v,t)  3 (p,q,v)  4 (t,p,v)  5 (v,p,q).
// So 0 is red, 60 yellow, 120 green, 180 cyan, 240 blue, 300 magenta, and
// s = 0 gives the grey (v, v, v).
#include "math_detail.h"

using karma::me::detail::kOne;
using karma::me::detail::kZero;

namespace {

MeReal clamp01(MeReal x) {
  if (!(x > kZero)) return kZero;  // also maps NaN to 0
  return x < kOne ? x : kOne;
}

}  // namespace

extern "C" {

void MEAPI MeHSVtoRGB(MeReal h, MeReal s, MeReal v, float rgb[3]) {
  const MeReal full = MeReal(360);
  if (!std::isfinite(h)) h = kZero;
  h = MeFmod(h, full);  // in (-360, 360)
  if (h < kZero) h += full;
  if (!(h < full)) h = kZero;  // -tiny + 360 can round up to 360
  s = clamp01(s);
  v = clamp01(v);

  const MeReal sector = h / MeReal(60);  // in [0, 6)
  int i = static_cast<int>(sector);
  if (i > 5) i = 5;
  const MeReal f = sector - static_cast<MeReal>(i);
  const MeReal p = v * (kOne - s);
  const MeReal q = v * (kOne - s * f);
  const MeReal t = v * (kOne - s * (kOne - f));
  MeReal r, g, b;
  switch (i) {
    case 0:
      r = v, g = t, b = p;
      break;
    case 1:
      r = q, g = v, b = p;
      break;
    case 2:
      r = p, g = v, b = t;
      break;
    case 3:
      r = p, g = q, b = v;
      break;
    case 4:
      r = t, g = p, b = v;
      break;
    default:
      r = v, g = p, b = q;
      break;
  }
  rgb[0] = static_cast<float>(r);
  rgb[1] = static_cast<float>(g);
  rgb[2] = static_cast<float>(b);
}

}  // extern "C"
