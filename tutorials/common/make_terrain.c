/* make_terrain.c: writes terrain2.bmp, the height map of the tutorials'
 * terrain (QuadBike's HeightFieldFromBMP(&hf, "terrain2", 15), CarTerrain),
 * into the directory given as the only argument.
 *
 * 64 x 64 pixels, 8-bit grey (a 256-entry grey palette); level 255 is the
 * height scale the program passes (15 m in QuadBike). With the height
 * field's 2 m spacing the terrain is 126 m square, centred on the origin:
 *   h(x, z) = 2 m + ramp(r) (1.8 m sin(2 pi x / 64 m) cos(2 pi z / 48 m)
 *                            + 0.6 m sin(2 pi (0.6 x + 0.8 z) / 22 m))
 *             + rim(r)
 * where r is the distance from the origin, ramp grows smoothly from 0 at
 * r = 6 m to 1 at r = 20 m (a flat start area), and rim raises the outer
 * 12 m of the map by up to 10 m so vehicles stay in. Slopes stay below
 * about 20 degrees inside the rim. The formula is evaluated in double and
 * rounded to a level, so another C library's sin could change a pixel only
 * if it fell within ~1e-13 of a half level. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>

#define SIZE 64
#define SPACING 2.0
#define SCALE 15.0

static double Smooth(double a, double b, double x) {
  double t = (x - a) / (b - a);
  if (t < 0) t = 0;
  if (t > 1) t = 1;
  return t * t * (3 - 2 * t);
}

static double Height(double x, double z) {
  const double pi = 3.14159265358979323846;
  const double r = sqrt(x * x + z * z);
  const double edge = fmax(fabs(x), fabs(z));
  const double hills = 1.8 * sin(2 * pi * x / 64) * cos(2 * pi * z / 48) + 0.6 * sin(2 * pi * (0.6 * x + 0.8 * z) / 22);
  return 2.0 + Smooth(6, 20, r) * hills + 10.0 * Smooth(51, 63, edge);
}

static void Put16(FILE *f, unsigned v) {
  fputc((int)(v & 255), f);
  fputc((int)((v >> 8) & 255), f);
}
static void Put32(FILE *f, uint32_t v) {
  Put16(f, v & 0xffff);
  Put16(f, v >> 16);
}

int main(int argc, char **argv) {
  char path[4096];
  FILE *f;
  int row, col, i;
  const uint32_t palette = 256 * 4, pixels = SIZE * SIZE; /* rows of 64 bytes: no padding */
  if (argc != 2) {
    fprintf(stderr, "usage: karma-make-terrain DIR\n");
    return 2;
  }
  snprintf(path, sizeof path, "%s/terrain2.bmp", argv[1]);
  f = fopen(path, "wb");
  if (!f) {
    fprintf(stderr, "karma-make-terrain: cannot write %s\n", path);
    return 1;
  }
  /* BITMAPFILEHEADER + BITMAPINFOHEADER, 8 bits per pixel, bottom-up rows. */
  fputc('B', f);
  fputc('M', f);
  Put32(f, 14 + 40 + palette + pixels);
  Put32(f, 0);
  Put32(f, 14 + 40 + palette);
  Put32(f, 40);
  Put32(f, SIZE);
  Put32(f, SIZE);
  Put16(f, 1);
  Put16(f, 8);
  Put32(f, 0);
  Put32(f, pixels);
  Put32(f, 2835);
  Put32(f, 2835);
  Put32(f, 256);
  Put32(f, 0);
  for (i = 0; i < 256; ++i) {
    fputc(i, f);
    fputc(i, f);
    fputc(i, f);
    fputc(0, f);
  }
  /* File row 0 is the bottom image row (the last pixel row, r = SIZE - 1).
   * Pixel (column c, row r) is grid point (ix = c, iz = r). */
  for (row = SIZE - 1; row >= 0; --row)
    for (col = 0; col < SIZE; ++col) {
      const double x = (col - (SIZE - 1) / 2.0) * SPACING, z = (row - (SIZE - 1) / 2.0) * SPACING;
      double level = floor(Height(x, z) / SCALE * 255.0 + 0.5);
      if (level < 0) level = 0;
      if (level > 255) level = 255;
      fputc((int)level, f);
    }
  if (fclose(f) != 0) {
    fprintf(stderr, "karma-make-terrain: error writing %s\n", path);
    return 1;
  }
  return 0;
}
