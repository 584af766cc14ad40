// The rendering context (mjr_makeContext) printed for comparison against 2.2.2, under OSMesa:
// every mjrContext field but GL-independent pointers, then the content of what it made, each
// drawn or read back by plain GL here and hashed: built-in shapes, plane grids, meshes and
// their convex hulls, height fields, font bitmaps, textures with their mipmaps, skin buffers.
//   render_context MODEL...
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <mujoco/mujoco.h>

#define W 256
#define H 256
static unsigned char buffer[4 * W * H];

static unsigned long long fnv(const void* p, size_t n) {
  const unsigned char* b = (const unsigned char*)p;
  unsigned long long h = 1469598103934665603ULL;
  for (size_t i = 0; i < n; i++) h = (h ^ b[i]) * 1099511628211ULL;
  return h;
}

static void ints(const char* name, const int* v, int n) {
  printf(" %s", name);
  for (int i = 0; i < n; i++) printf(" %d", v[i]);
  printf("\n");
}

static void print_context(const mjrContext* c) {
  printf(" floats %a %a %a %a %a fog %a %a %a %a\n", c->lineWidth, c->shadowClip,
         c->shadowScale, c->fogStart, c->fogEnd, c->fogRGBA[0], c->fogRGBA[1], c->fogRGBA[2],
         c->fogRGBA[3]);
  printf(" shadowSize %d off %d %d %d fontScale %d\n", c->shadowSize, c->offWidth,
         c->offHeight, c->offSamples, c->fontScale);
  ints("aux", c->auxWidth, mjNAUX);
  printf(" off fbo %u %u color %u %u depth %u %u shadow %u %u\n", c->offFBO, c->offFBO_r,
         c->offColor, c->offColor_r, c->offDepthStencil, c->offDepthStencil_r, c->shadowFBO,
         c->shadowTex);
  printf(" ntexture %d\n", c->ntexture);
  for (int i = 0; i < c->ntexture; i++) printf("  texture %d type %d\n", c->texture[i], c->textureType[i]);
  printf(" lists plane %u %d mesh %u %d hfield %u %d builtin %u %d font %u %u %u %d\n",
         c->basePlane, c->rangePlane, c->baseMesh, c->rangeMesh, c->baseHField, c->rangeHField,
         c->baseBuiltin, c->rangeBuiltin, c->baseFontNormal, c->baseFontShadow, c->baseFontBig,
         c->rangeFont);
  printf(" nskin %d\n", c->nskin);
  for (int i = 0; i < c->nskin; i++) {
    printf("  skin vbo %u %u %u %u\n", c->skinvertVBO[i], c->skinnormalVBO[i],
           c->skintexcoordVBO[i], c->skinfaceVBO[i]);
  }
  ints("charWidth", c->charWidth + 32, 95);
  ints("charWidthBig", c->charWidthBig + 32, 95);
  printf(" charHeight %d %d\n", c->charHeight, c->charHeightBig);
  printf(" window %d %d %d %d %d current %d\n", c->glInitialized, c->windowAvailable,
         c->windowSamples, c->windowStereo, c->windowDoublebuffer, c->currentBuffer);
}

// draws display list `list` lit, seen from a fixed direction within a box of half size `r`,
// and prints a hash of the pixels
static void draw(const char* what, int id, GLuint list, double r) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glReadBuffer(GL_FRONT);
  glDrawBuffer(GL_FRONT);
  glViewport(0, 0, W, H);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-r, r, -r, r, -10 * r, 10 * r);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(-60, 1, 0, 0);
  glRotatef(30, 0, 0, 1);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  float pos[4] = {0.3f, -0.5f, 1, 0};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glColor4f(1, 1, 1, 1);
  glCallList(list);
  glFinish();
  static unsigned char rgb[3 * W * H];
  glReadPixels(0, 0, W, H, GL_RGB, GL_UNSIGNED_BYTE, rgb);
  long lit = 0;
  for (int i = 0; i < 3 * W * H; i++) lit += rgb[i] != 0;
  printf(" draw %s %d lit %ld hash %016llx\n", what, id, lit, fnv(rgb, sizeof rgb));
}

static double maxabs(const float* v, int n) {
  double r = 1e-6;
  for (int i = 0; i < n; i++) r = fabs(v[i]) > r ? fabs(v[i]) : r;
  return r;
}

static void fonts(const mjrContext* c);
static void textures_and_skins(const mjrContext* c);

static void content(const mjModel* m, const mjrContext* c) {
  for (int i = 0; i < c->rangeBuiltin; i++) draw("builtin", i, c->baseBuiltin + i, 2.5);
  int plane = 0;
  draw("plane", 0, c->basePlane, 1.5);
  for (int g = 0; g < m->ngeom; g++) {
    if (m->geom_type[g] != mjGEOM_PLANE) continue;
    plane++;
    double r = m->geom_size[3 * g] > 0 ? 1.2 * m->geom_size[3 * g] : 20 * m->stat.extent;
    draw("plane", plane, c->basePlane + plane, r);
  }
  for (int i = 0; i < m->nmesh; i++) {
    double r = 1.5 * maxabs(m->mesh_vert + 3 * m->mesh_vertadr[i], 3 * m->mesh_vertnum[i]);
    draw("mesh", i, c->baseMesh + 2 * i, r);
    if (m->mesh_graphadr[i] >= 0) draw("hull", i, c->baseMesh + 2 * i + 1, r);
  }
  for (int i = 0; i < m->nhfield; i++) {
    const mjtNum* s = m->hfield_size + 4 * i;
    double r = 1.5 * (s[0] > s[1] ? s[0] : s[1]);
    r = r > s[2] + s[3] ? r : 1.5 * (s[2] + s[3]);
    draw("hfield", i, c->baseHField + i, r);
  }
  fonts(c);
  textures_and_skins(c);
  printf(" glerror %d\n", mjr_getError());
}

// every character of each font at the raster position
static void fonts(const mjrContext* c) {
  GLuint bases[3] = {c->baseFontNormal, c->baseFontShadow, c->baseFontBig};
  for (int f = 0; f < 3; f++) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDrawBuffer(GL_FRONT);
    glReadBuffer(GL_FRONT);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
    glColor3f(1, 1, 1);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    for (int row = 0; row < 6; row++) {
      glWindowPos2i(2, H - 40 - 36 * row);
      glListBase(bases[f]);
      char text[17];
      for (int k = 0; k < 16; k++) {
        int ch = 32 + 16 * row + k;
        text[k] = ch <= 126 ? ch : ' ';
      }
      glCallLists(16, GL_UNSIGNED_BYTE, text);
    }
    static unsigned char rgb[3 * W * H];
    glReadPixels(0, 0, W, H, GL_RGB, GL_UNSIGNED_BYTE, rgb);
    printf(" font %d hash %016llx\n", f, fnv(rgb, sizeof rgb));
  }
}

// textures with their mipmap levels, skin buffers
static void textures_and_skins(const mjrContext* c) {
  for (int i = 0; i < c->ntexture; i++) {
    GLenum target = c->textureType[i] == mjTEXTURE_2D ? GL_TEXTURE_2D : GL_TEXTURE_CUBE_MAP;
    GLenum face = target == GL_TEXTURE_2D ? GL_TEXTURE_2D : GL_TEXTURE_CUBE_MAP_POSITIVE_X;
    glBindTexture(target, c->texture[i]);
    for (int level = 0; level < 3; level++) {
      GLint w = 0, h = 0;
      glGetTexLevelParameteriv(face, level, GL_TEXTURE_WIDTH, &w);
      glGetTexLevelParameteriv(face, level, GL_TEXTURE_HEIGHT, &h);
      if (!w || !h) break;
      unsigned char* px = malloc(3 * (size_t)w * h);
      glGetTexImage(face, level, GL_RGB, GL_UNSIGNED_BYTE, px);
      printf(" texture %d level %d %dx%d hash %016llx\n", i, level, w, h, fnv(px, 3 * (size_t)w * h));
      free(px);
    }
  }
  // skin buffers
  for (int i = 0; i < c->nskin; i++) {
    GLuint bufs[2] = {c->skintexcoordVBO[i], c->skinfaceVBO[i]};
    for (int k = 0; k < 2; k++) {
      if (!bufs[k]) continue;
      glBindBuffer(GL_ARRAY_BUFFER, bufs[k]);
      GLint size = 0;
      glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &size);
      unsigned char* data = malloc(size ? size : 1);
      glGetBufferSubData(GL_ARRAY_BUFFER, 0, size, data);
      printf(" skin %d buffer %d size %d hash %016llx\n", i, k, size, fnv(data, size));
      free(data);
    }
  }
}

int main(int argc, char** argv) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) {
    fprintf(stderr, "no OSMesa context\n");
    return 2;
  }
  mjrContext con;
  mjr_defaultContext(&con);
  mjr_makeContext(NULL, &con, 130);
  printf("no model\n");
  print_context(&con);
  for (int scale = 50; scale <= 300; scale += 50) {
    mjr_changeFont(scale, &con);
    ints("font", con.charWidth + 32, 95);
    fonts(&con);
  }
  mjr_addAux(0, 100, 80, 4, &con);
  mjr_addAux(1, 64, 64, 0, &con);
  print_context(&con);
  mjr_freeContext(&con);
  print_context(&con);
  for (int a = 1; a < argc; a++) {
    char err[1000] = "";
    mjModel* m = mj_loadXML(argv[a], NULL, err, sizeof err);
    printf("model %s\n", argv[a]);
    if (!m) {
      printf(" load error: %s\n", err);
      continue;
    }
    mjr_makeContext(m, &con, 150);
    print_context(&con);
    content(m, &con);
    mjr_freeContext(&con);
    mj_deleteModel(m);
  }
  return 0;
}
