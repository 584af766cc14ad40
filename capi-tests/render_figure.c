// 2D figures (mjr_figure) printed for comparison against 2.2.2, under OSMesa: a series of
// figures covering every field of mjvFigure, at several viewports and font scales. Per case:
// the fields mjr_figure writes back and a hash of the pixels of the whole buffer.
//   render_figure [PPMDIR]   (PPMDIR: also write each case's image there)
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <mujoco/mujoco.h>

#define W 640
#define H 480
static unsigned char buffer[4 * W * H];
static unsigned char rgb[3 * W * H];
static mjrContext con;
static mjvFigure fig;
static const char* ppmdir = NULL;
static int ncase = 0;
static int offscreen = 0;  // read the multisampled offscreen buffer through mjr_readPixels

// a model only for its offscreen buffer: 4 samples at the size of the window
static const char* xml =
    "<mujoco><visual><global offwidth='640' offheight='480'/>"
    "<quality offsamples='4'/></visual><worldbody/></mujoco>";

static unsigned long long fnv(const void* p, size_t n) {
  const unsigned char* b = (const unsigned char*)p;
  unsigned long long h = 1469598103934665603ULL;
  for (size_t i = 0; i < n; i++) h = (h ^ b[i]) * 1099511628211ULL;
  return h;
}

static mjrRect rect(int l, int b, int w, int h) {
  mjrRect r = {l, b, w, h};
  return r;
}

// clears the buffer to a fixed color
static void clear(void) {
  glViewport(0, 0, W, H);
  glClearColor(0.15f, 0.2f, 0.25f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

// prints the fields mjr_figure writes and a hash of the buffer
static void finish(const char* name) {
  glFinish();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  if (offscreen) {
    mjr_readPixels(rgb, NULL, rect(0, 0, W, H), &con);
  } else {
    glReadPixels(0, 0, W, H, GL_RGB, GL_UNSIGNED_BYTE, rgb);
  }
  printf("case %d %s: pixel %d %d %d %d data %a %a %a %a range %a %a %a %a hl %d glerr %d "
         "hash %016llx\n",
         ncase, name, fig.xaxispixel[0], fig.xaxispixel[1], fig.yaxispixel[0],
         fig.yaxispixel[1], fig.xaxisdata[0], fig.xaxisdata[1], fig.yaxisdata[0],
         fig.yaxisdata[1], fig.range[0][0], fig.range[0][1], fig.range[1][0], fig.range[1][1],
         fig.highlightid, glGetError(), fnv(rgb, sizeof(rgb)));
  // GL state mjr_figure leaves behind
  GLint mode, vp[4], base;
  GLfloat color[4], width, raster[4], proj[16];
  glGetIntegerv(GL_MATRIX_MODE, &mode);
  glGetIntegerv(GL_VIEWPORT, vp);
  glGetIntegerv(GL_LIST_BASE, &base);
  glGetFloatv(GL_CURRENT_COLOR, color);
  glGetFloatv(GL_LINE_WIDTH, &width);
  glGetFloatv(GL_CURRENT_RASTER_POSITION, raster);
  glGetFloatv(GL_PROJECTION_MATRIX, proj);
  printf(" state mode %x viewport %d %d %d %d base %d color %a %a %a %a width %a array %d "
         "blend %d raster %a %a proj %016llx\n",
         mode, vp[0], vp[1], vp[2], vp[3], base - (GLint)con.baseFontNormal, color[0], color[1],
         color[2], color[3], width, glIsEnabled(GL_VERTEX_ARRAY), glIsEnabled(GL_BLEND),
         raster[0], raster[1], fnv(proj, sizeof(proj)));
  glDisableClientState(GL_VERTEX_ARRAY);
  if (ppmdir) {
    char path[1000];
    snprintf(path, sizeof(path), "%s/%03d.ppm", ppmdir, ncase);
    FILE* f = fopen(path, "wb");
    if (f) {
      fprintf(f, "P6 %d %d 255\n", W, H);
      for (int r = H - 1; r >= 0; r--) fwrite(rgb + 3 * W * r, 1, 3 * W, f);
      fclose(f);
    }
  }
  ncase++;
}

// default figure with the write-back fields set to a marker
static void reset(void) {
  mjv_defaultFigure(&fig);
  fig.xaxispixel[0] = fig.xaxispixel[1] = fig.yaxispixel[0] = fig.yaxispixel[1] = -7;
  fig.xaxisdata[0] = fig.xaxisdata[1] = fig.yaxisdata[0] = fig.yaxisdata[1] = -7;
}

// nline lines of npnt points: phase-shifted sines over [x0, x0+span]
static void lines(int nline, int npnt, float x0, float span, float amp) {
  for (int n = 0; n < nline; n++) {
    fig.linepnt[n] = npnt;
    for (int i = 0; i < npnt; i++) {
      float x = x0 + span * i / (float)(npnt > 1 ? npnt - 1 : 1);
      fig.linedata[n][2 * i] = x;
      fig.linedata[n][2 * i + 1] = amp * sinf(0.05f * i + 0.7f * n) + 0.1f * n;
    }
  }
}

static void names(int nline, const char* prefix) {
  for (int n = 0; n < nline; n++) snprintf(fig.linename[n], 100, "%s %d", prefix, n);
}

static void draw(const char* name, mjrRect vp) {
  clear();
  mjr_figure(vp, &fig, &con);
  finish(name);
}

static const mjrRect FULL = {0, 0, W, H};

// a figure using most features, for the font-scale sweep
static void full_figure(void) {
  reset();
  lines(4, 200, 0, 10, 1.5f);
  names(4, "line");
  strcpy(fig.title, "Sensor data  Joint positions  Forces");
  fig.subplot = 1;
  strcpy(fig.xlabel, "time (s)");
  fig.gridsize[0] = 6;
  fig.gridsize[1] = 5;
  fig.flg_selection = 1;
  fig.selection = 4.2f;
  fig.highlightid = 1;
}

int main(int argc, char** argv) {
  if (argc > 1) ppmdir = argv[1];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) {
    fprintf(stderr, "no OSMesa context\n");
    return 1;
  }
  mjr_defaultContext(&con);
  mjr_makeContext(NULL, &con, 100);
  mjr_setBuffer(mjFB_WINDOW, &con);
  printf("font %d charHeight %d\n", con.fontScale, con.charHeight);

  // defaults
  reset();
  draw("default empty", FULL);
  reset();
  draw("default small", rect(20, 30, 300, 200));
  reset();
  lines(3, 100, 0, 5, 1);
  draw("three lines", FULL);
  names(3, "name");
  draw("legend names", FULL);
  strcpy(fig.title, "A title");
  strcpy(fig.xlabel, "x label");
  draw("title xlabel", FULL);
  fig.xlabel[0] = 0;
  draw("title only", FULL);
  fig.title[0] = 0;
  strcpy(fig.xlabel, "only an x label, rather long to be centered");
  draw("xlabel only", FULL);

  // legend: offset, overflow, highlight point
  reset();
  lines(8, 50, -2, 4, 2);
  names(8, "signal");
  fig.legendoffset = 3;
  draw("legendoffset 3", FULL);
  fig.legendoffset = 0;
  fig.linename[2][0] = 0;
  strcpy(fig.linename[5], "a much longer legend entry");
  draw("legend gap long", FULL);
  fig.flg_legend = 0;
  draw("legend off", FULL);
  fig.flg_legend = 1;
  {
    int ch = con.charHeight, pad = ch / 2;
    for (int k = 0; k < 4; k++) {
      fig.highlight[0] = fig.xaxispixel[1] - pad - 3;
      fig.highlight[1] = fig.yaxispixel[1] - pad - ch * k - ch / 3;
      char name[50];
      snprintf(name, sizeof(name), "highlight row %d", k);
      draw(name, FULL);
    }
    fig.highlight[0] = 5;
    fig.highlight[1] = 5;
    draw("highlight outside", FULL);
  }
  reset();
  lines(60, 20, 0, 1, 1);
  names(60, "many");
  draw("legend overflow", rect(0, 0, 400, 300));
  draw("legend overflow tiny", rect(10, 10, 200, 60));

  // highlight id and selection
  reset();
  lines(3, 300, 0, 3, 1);
  names(3, "q");
  fig.highlightid = 2;
  draw("highlightid 2", FULL);
  fig.flg_selection = 1;
  fig.selection = 1.37f;
  draw("selection highlight", FULL);
  fig.highlightid = -1;
  draw("selection only", FULL);
  fig.selection = -5;
  draw("selection outside", FULL);
  fig.highlightid = 5;
  fig.selection = 1;
  draw("highlight empty line", FULL);
  fig.highlightid = 0;
  fig.linepnt[0] = 0;
  draw("highlight empty first line", FULL);

  // ranges
  reset();
  lines(2, 100, 0, 10, 3);
  fig.range[0][0] = -1;
  fig.range[0][1] = 20;
  fig.range[1][0] = -2;
  fig.range[1][1] = 2;
  fig.flg_extend = 0;
  draw("range fixed", FULL);
  fig.flg_extend = 1;
  draw("range fixed extend", FULL);
  fig.range[0][0] = fig.range[0][1] = 0;
  fig.range[1][0] = 1;
  fig.range[1][1] = -1;
  fig.flg_extend = 0;
  draw("range auto", FULL);
  fig.flg_symmetric = 1;
  draw("symmetric", FULL);
  fig.range[1][0] = -0.5f;
  fig.range[1][1] = 4;
  draw("symmetric fixed", FULL);
  reset();
  lines(1, 10, 0, 1, 0);
  fig.linedata[0][1] = fig.linedata[0][3] = 0;
  for (int i = 0; i < 10; i++) fig.linedata[0][2 * i + 1] = 0.25f;
  fig.range[1][0] = fig.range[1][1] = 0;
  draw("flat data", FULL);
  fig.range[0][0] = fig.range[0][1] = 3;
  fig.linepnt[0] = 0;
  draw("empty auto", FULL);
  reset();
  lines(2, 100, 0, 1, 1);
  fig.linedata[0][20] = NAN;
  fig.linedata[0][41] = INFINITY;
  fig.linedata[1][0] = -INFINITY;
  fig.range[0][0] = fig.range[0][1] = 0;
  fig.range[1][0] = fig.range[1][1] = 0;
  draw("nonfinite data", FULL);
  reset();
  lines(2, 1000, -100, 1000, 500);
  draw("max points large values", FULL);
  fig.linepnt[0] = 1;
  fig.linepnt[1] = 2;
  draw("one and two points", FULL);

  // grid and tick labels
  reset();
  lines(2, 100, 0, 7, 1.3f);
  int grids[][2] = {{5, 5}, {10, 3}, {25, 25}, {1, 5}, {5, 1}, {3, 12}, {20, 20}};
  for (int k = 0; k < 7; k++) {
    fig.gridsize[0] = grids[k][0];
    fig.gridsize[1] = grids[k][1];
    char name[50];
    snprintf(name, sizeof(name), "grid %d %d", grids[k][0], grids[k][1]);
    draw(name, FULL);
  }
  fig.gridsize[0] = 6;
  fig.gridsize[1] = 7;
  const char* formats[][2] = {{"%.1f", "%.3f"}, {"%g", "%g"}, {"%.2e", "%5.1f"},
                              {"%.3f s", "[%.1f]"}, {"%.0f", "%.10f"}, {"%08.3f", "%+.2g"}};
  for (int k = 0; k < 6; k++) {
    strcpy(fig.xformat, formats[k][0]);
    strcpy(fig.yformat, formats[k][1]);
    char name[50];
    snprintf(name, sizeof(name), "format %s %s", formats[k][0], formats[k][1]);
    draw(name, FULL);
  }
  strcpy(fig.xformat, "%.1f");
  strcpy(fig.yformat, "%.2g");
  fig.minwidth[0] = 0;
  draw("minwidth empty", FULL);
  strcpy(fig.minwidth, "XXXXXXXXXXXX");
  draw("minwidth wide", FULL);
  strcpy(fig.minwidth, "XXX");
  int ticks[][2] = {{0, 1}, {1, 0}, {0, 0}};
  for (int k = 0; k < 3; k++) {
    fig.flg_ticklabel[0] = ticks[k][0];
    fig.flg_ticklabel[1] = ticks[k][1];
    char name[50];
    snprintf(name, sizeof(name), "ticklabel %d %d", ticks[k][0], ticks[k][1]);
    draw(name, FULL);
  }

  // styles
  reset();
  lines(5, 80, 0, 1, 1);
  names(5, "styled");
  fig.flg_barplot = 1;
  draw("barplot", FULL);
  fig.flg_barplot = 0;
  fig.linewidth = 1;
  fig.gridwidth = 2.5f;
  fig.gridsize[0] = fig.gridsize[1] = 4;
  draw("widths", FULL);
  fig.linewidth = 5.5f;
  float figrgba[4] = {0.3f, 0.1f, 0.5f, 0.6f}, panergba[4] = {0.9f, 0.9f, 0.8f, 0.7f};
  float legendrgba[4] = {0.2f, 0.6f, 0.2f, 0.8f}, gridrgb[3] = {0.9f, 0.1f, 0.1f};
  float textrgb[3] = {0.2f, 0.9f, 0.4f};
  memcpy(fig.figurergba, figrgba, sizeof(figrgba));
  memcpy(fig.panergba, panergba, sizeof(panergba));
  memcpy(fig.legendrgba, legendrgba, sizeof(legendrgba));
  memcpy(fig.gridrgb, gridrgb, sizeof(gridrgb));
  memcpy(fig.textrgb, textrgb, sizeof(textrgb));
  strcpy(fig.title, "Colored");
  strcpy(fig.xlabel, "colored x");
  fig.flg_selection = 1;
  fig.selection = 0.5f;
  fig.highlightid = 3;
  draw("colors", FULL);
  for (int k = 0; k < 3; k++) fig.linergb[k][k] = 0.05f;
  draw("line colors", rect(100, 50, 500, 400));

  // subplot titles
  reset();
  lines(2, 50, 0, 1, 1);
  strcpy(fig.title, "First plot  Second plot   Third  Last one here");
  for (int k = 0; k < 5; k++) {
    fig.subplot = k;
    char name[50];
    snprintf(name, sizeof(name), "subplot %d", k);
    draw(name, rect(0, 0, 300, 250));
  }
  fig.subplot = 2;
  draw("subplot wide", FULL);
  strcpy(fig.title, "a single space title and more words");
  fig.subplot = 0;
  draw("single spaces", rect(0, 0, 200, 200));
  memset(fig.title, 'W', sizeof(fig.title) - 1);
  fig.title[sizeof(fig.title) - 1] = 0;
  draw("title overflow", rect(0, 0, 200, 200));
  strcpy(fig.title, "ab");
  fig.title[3] = 'Z';
  fig.title[4] = 'Y';
  draw("title garbage after nul", rect(0, 0, 200, 200));

  // viewports
  reset();
  lines(3, 60, 0, 2, 1);
  names(3, "v");
  strcpy(fig.title, "Viewport");
  strcpy(fig.xlabel, "x");
  mjrRect vps[] = {{0, 0, 0, 0},     {10, 10, 1, 1},   {10, 10, 2, 2},   {10, 10, 10, 10},
                   {5, 5, 30, 20},   {50, 40, 80, 60}, {0, 0, 640, 60},  {0, 0, 90, 480},
                   {300, 200, 340, 280}, {0, 0, 25, 40}, {0, 0, 60, 25},  {0, 0, 40, 34}};
  for (int k = 0; k < 12; k++) {
    char name[50];
    fig.xaxispixel[0] = -7;
    snprintf(name, sizeof(name), "viewport %d %d %d %d", vps[k].left, vps[k].bottom,
             vps[k].width, vps[k].height);
    draw(name, vps[k]);
  }

  // edge cases
  reset();
  lines(3, 100, 0, 1, 1);
  names(3, "edge");
  strcpy(fig.xformat, "%0120.2f");
  strcpy(fig.yformat, "%% %.1f %%");
  draw("formats long and percent", FULL);
  strcpy(fig.xformat, "%.1f");
  strcpy(fig.yformat, "%.2g");
  fig.linepnt[0] = 1500;
  fig.linepnt[1] = -3;
  fig.flg_selection = 1;
  fig.selection = 0.7f;
  fig.highlightid = 0;
  draw("linepnt past line and negative", FULL);
  reset();
  lines(2, 101, 0, 1, 1);
  fig.flg_barplot = 1;
  fig.figurergba[3] = 0;
  fig.legendrgba[3] = 0;
  names(2, "\xe9t\xe9 \x80\xff~");
  strcpy(fig.title, "caf\xe9  \xc3\xa9t\xc3\xa9");
  fig.subplot = 1;
  draw("barplot odd transparent high chars", FULL);
  reset();
  lines(2, 50, 0, 1, 1e-6f);
  fig.range[1][0] = fig.range[1][1] = 0;
  fig.flg_symmetric = 1;
  fig.gridsize[0] = fig.gridsize[1] = 4;
  strcpy(fig.yformat, "%.3g");
  draw("tiny range symmetric", FULL);
  reset();
  lines(1, 3, 0, 1, 1);
  fig.linedata[0][1] = 3e38f;
  fig.linedata[0][3] = -3e38f;
  fig.range[1][0] = fig.range[1][1] = 0;
  draw("huge values", FULL);
  reset();
  lines(2, 40, 0, 1, 1);
  strcpy(fig.title, "A rather long title that does not fit into a narrow figure at all");
  draw("long title narrow", rect(100, 100, 150, 200));
  strcpy(fig.title, "Left  Middle title  Right side text goes here");
  fig.subplot = 1;
  draw("subplot neighbours cut", rect(0, 0, 170, 200));
  clear();
  mjr_figure(rect(10, 10, 1, 1), &fig, &con);
  mjr_overlay(mjFONT_NORMAL, mjGRID_TOPLEFT, FULL, "after a one-pixel figure", "x", &con);
  mjr_figure(rect(10, 10, 40, 30), &fig, &con);
  mjr_rectangle(rect(200, 200, 50, 50), 1, 0, 0, 0.5f);
  mjr_text(mjFONT_BIG, "text after figures", &con, 0.3f, 0.5f, 1, 1, 0);
  finish("figures then text");

  // four figures in one frame
  clear();
  for (int k = 0; k < 4; k++) {
    reset();
    lines(k + 1, 40 * (k + 1), (float)k, 1, 1);
    names(k + 1, "sub");
    fig.flg_barplot = k == 3;
    mjr_figure(rect((k % 2) * W / 2, (k / 2) * H / 2, W / 2, H / 2), &fig, &con);
  }
  finish("four panels");

  // font scales
  int scales[] = {50, 100, 150, 200, 250, 300};
  for (int k = 0; k < 6; k++) {
    mjr_changeFont(scales[k], &con);
    full_figure();
    char name[50];
    snprintf(name, sizeof(name), "fontscale %d charHeight %d", scales[k], con.charHeight);
    draw(name, FULL);
    draw(name, rect(40, 30, 320, 240));
  }

  mjr_freeContext(&con);

  // multisampled offscreen buffer
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  mj_makeEmptyFileVFS(&vfs, "figure.xml", (int)strlen(xml));
  memcpy(vfs.filedata[0], xml, strlen(xml));
  char error[500] = "";
  mjModel* m = mj_loadXML("figure.xml", &vfs, error, sizeof(error));
  if (!m) {
    fprintf(stderr, "model: %s\n", error);
    return 1;
  }
  mjr_defaultContext(&con);
  mjr_makeContext(m, &con, 150);
  mjr_setBuffer(mjFB_OFFSCREEN, &con);
  offscreen = 1;
  printf("offscreen %d %d samples %d\n", con.offWidth, con.offHeight, con.offSamples);
  full_figure();
  draw("msaa full", FULL);
  draw("msaa small", rect(33, 21, 287, 190));
  fig.flg_barplot = 1;
  fig.gridsize[0] = 11;
  fig.gridsize[1] = 9;
  fig.gridwidth = 1.5f;
  draw("msaa barplot grid", rect(7, 3, 611, 457));
  reset();
  lines(5, 1000, -3, 6, 2);
  names(5, "dense");
  fig.flg_symmetric = 1;
  fig.linewidth = 1.3f;
  fig.highlightid = 4;
  draw("msaa dense", FULL);
  mjr_freeContext(&con);
  mj_deleteModel(m);
  mj_deleteVFS(&vfs);
  OSMesaDestroyContext(ctx);
  printf("cases %d\n", ncase);
  return 0;
}
