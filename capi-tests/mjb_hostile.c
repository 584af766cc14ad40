// Hostile MJB files, built against each library (tests/mjb_hostile.rs):
//   mjb_hostile save IN.xml OUT.mjb       compiles a model and writes its MJB
//   mjb_hostile mutants SEED N FILE.mjb...
//       N mutants of the files (byte flips, truncation, size fields set to extremes, zeroed
//       regions, header changes, index entries set to extremes), each loaded in a child (from a
//       file for even mutants, from a VFS buffer for odd ones) and, when it loads, stepped 100
//       times with controls. One line per mutant: "<i> <kind> <verdict>", verdict one of
//       "reject <warning>", "error <mju_error text>", "ok", "crash <signal>", "hang".
//   mjb_hostile roundtrip FILE.xml...
//       each model that loads, saved to a buffer and loaded back from a VFS: "same" when the
//       reloaded model saves to the same bytes, else "differs" or "reject <warning>".
//   mjb_hostile probe FILE.mjb
//       fixed cases with 2.2.2's behaviour to match: trailing bytes, truncation, header.
#include "child.h"  // first: it sets the feature macros
#include <limits.h>
#include <mujoco/mjxmacro.h>
#include <stdlib.h>
#include <string.h>

static char last_warning[1000];

static void keep_warning(const char* msg) {
  strncpy(last_warning, msg, sizeof last_warning - 1);
}

static void report_error(const char* msg) {
  printf("error %s\n", msg);
  fflush(stdout);
  _exit(0);
}

static unsigned long long rng_state;

static unsigned long long rnd(void) {
  unsigned long long z = (rng_state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

static size_t below(size_t n) { return n ? (size_t)(rnd() % n) : 0; }

static unsigned char* read_all(const char* path, size_t* size) {
  FILE* f = fopen(path, "rb");
  if (!f) return NULL;
  fseek(f, 0, SEEK_END);
  long n = ftell(f);
  fseek(f, 0, SEEK_SET);
  unsigned char* b = malloc(n > 0 ? n : 1);
  *size = fread(b, 1, n, f);
  fclose(f);
  return b;
}

// the mutant under test, read by the child
static unsigned char* cur;
static size_t cur_size;
static int cur_vfs;
static char cur_path[512];

static void load_and_step(const char* unused) {
  (void)unused;
  mju_user_warning = keep_warning;
  mju_user_error = report_error;
  last_warning[0] = 0;
  mjModel* m = NULL;
  if (cur_vfs) {
    mjVFS* vfs = malloc(sizeof(mjVFS));
    mj_defaultVFS(vfs);
    if (mj_makeEmptyFileVFS(vfs, "m.mjb", (int)cur_size) == 0) {
      memcpy(vfs->filedata[vfs->nfile - 1], cur, cur_size);
      m = mj_loadModel("m.mjb", vfs);
    }
    mj_deleteVFS(vfs);
    free(vfs);
  } else {
    m = mj_loadModel(cur_path, NULL);
  }
  if (!m) {
    printf("reject %s\n", last_warning);
    return;
  }
  mjData* d = mj_makeData(m);
  if (!d) {
    printf("reject mjData: %s\n", last_warning);
    mj_deleteModel(m);
    return;
  }
  mj_forward(m, d);
  for (int s = 0; s < 100; s++) {
    drive_controls(m, d, s);
    mj_step(m, d);
  }
  printf("ok\n");
  mj_deleteData(d);
  mj_deleteModel(m);
}

static void run_case(int i, const char* kind, int vfs) {
  cur_vfs = vfs;
  if (!vfs) {
    FILE* f = fopen(cur_path, "wb");
    if (!f) return;
    fwrite(cur, 1, cur_size, f);
    fclose(f);
  }
  printf("%d %s %s ", i, kind, vfs ? "vfs" : "file");
  in_child(load_and_step, "", 20);
}

// the int fields after the 4-int header
static int nint_of(const unsigned char* b, size_t n) {
  int v = 0;
  if (n >= 16) memcpy(&v, b + 8, 4);
  return v;
}

// Byte ranges of a seed's int arrays in its MJB file (the file is the header, the int fields,
// mjOption, mjVisual, mjStatistic, then the arrays in X-macro order without padding).
typedef struct {
  size_t at[300], len[300];
  int n;
} IntArrays;

static void int_arrays(const mjModel* m, IntArrays* t) {
  size_t nint = 0;
#define X(name) nint++;
  MJMODEL_INTS
#undef X
  size_t pos = 16 + 4 * nint + sizeof(mjOption) + sizeof(mjVisual) + sizeof(mjStatistic);
  t->n = 0;
  MJMODEL_POINTERS_PREAMBLE(m)
#define X(type, name, nr, nc)                                        \
  {                                                                  \
    size_t len = sizeof(type) * (size_t)(m->nr) * (size_t)(nc);       \
    if (sizeof(type) == sizeof(int) && (type)0.5 == 0 && len && t->n < 300) { \
      t->at[t->n] = pos;                                             \
      t->len[t->n++] = len;                                          \
    }                                                                \
    pos += len;                                                      \
  }
  MJMODEL_POINTERS
#undef X
}

static const char* mutate(unsigned char* b, size_t* n, size_t orig, const IntArrays* t) {
  int nint = nint_of(b, orig);
  size_t ints_end = 16 + 4 * (size_t)(nint > 0 && nint < 1000 ? nint : 0);
  int extremes[] = {0, -1, INT_MAX, INT_MIN, 1, 1000000};
  switch (below(7)) {
    case 0: {
      int k = 1 + below(8);
      for (int j = 0; j < k; j++) b[below(*n)] ^= (unsigned char)(1u << below(8));
      return "flip";
    }
    case 1:
      *n = below(*n);
      return "truncate";
    case 2: {  // a size field: extreme, +1, doubled
      if (ints_end <= 16) return "none";
      size_t at = 16 + 4 * below((ints_end - 16) / 4);
      int v;
      memcpy(&v, b + at, 4);
      switch (below(3)) {
        case 0: v = extremes[below(6)]; break;
        case 1: v = v + 1; break;
        default: v = 2 * v; break;
      }
      memcpy(b + at, &v, 4);
      return "size";
    }
    case 3: {
      size_t at = below(*n), len = 1 + below(256);
      if (at + len > *n) len = *n - at;
      memset(b + at, 0, len);
      return "zero";
    }
    case 4: {
      int v = extremes[below(6)];
      memcpy(b + 4 * below(4), &v, 4);
      return "header";
    }
    default: {  // an entry of an int array (ids, addresses, types): an extreme or moved by one
      if (!t || !t->n) return "none";
      int a = (int)below(t->n);
      size_t at = t->at[a] + 4 * below(t->len[a] / 4);
      if (at + 4 > *n) return "none";
      int v;
      memcpy(&v, b + at, 4);
      v = below(2) ? extremes[below(6)] : v + (below(2) ? 1 : -1);
      memcpy(b + at, &v, 4);
      return "index";
    }
  }
}

int main(int argc, char** argv) {
  snprintf(cur_path, sizeof cur_path, "mjb_hostile_%d.mjb", (int)getpid());
  if (argc == 4 && !strcmp(argv[1], "save")) {
    char err[1000] = "";
    mjModel* m = mj_loadXML(argv[2], NULL, err, sizeof err);
    if (!m) {
      printf("reject %s\n", err);
      return 1;
    }
    mj_saveModel(m, argv[3], NULL, 0);
    mj_deleteModel(m);
    return 0;
  }
  if (argc >= 5 && !strcmp(argv[1], "mutants")) {
    rng_state = strtoull(argv[2], NULL, 10);
    const char* only = getenv("MJB_HOSTILE_ONLY");  // one mutant, kept as mutant.mjb
    int count = atoi(argv[3]), nfile = argc - 4;
    size_t* sizes = malloc(sizeof(size_t) * nfile);
    unsigned char** files = malloc(sizeof(unsigned char*) * nfile);
    IntArrays* tables = calloc(nfile, sizeof(IntArrays));
    for (int f = 0; f < nfile; f++) {
      files[f] = read_all(argv[4 + f], &sizes[f]);
      mjModel* m = mj_loadModel(argv[4 + f], NULL);
      if (m) {
        int_arrays(m, &tables[f]);
        mj_deleteModel(m);
      }
    }
    for (int i = 0; i < count; i++) {
      int f = (int)below(nfile);
      if (!files[f]) continue;
      cur_size = sizes[f];
      cur = malloc(cur_size ? cur_size : 1);
      memcpy(cur, files[f], cur_size);
      const char* kind = mutate(cur, &cur_size, sizes[f], &tables[f]);
      if (!only || atoi(only) == i) run_case(i, kind, i % 2);
      if (only && atoi(only) == i) {  // keep the mutant for a look
        FILE* keep = fopen("mutant.mjb", "wb");
        if (keep) {
          fwrite(cur, 1, cur_size, keep);
          fclose(keep);
        }
      }
      free(cur);
    }
    remove(cur_path);
    return 0;
  }
  if (argc >= 3 && !strcmp(argv[1], "roundtrip")) {
    mju_user_warning = keep_warning;
    for (int f = 2; f < argc; f++) {
      mjModel* m = mj_loadXML(argv[f], NULL, NULL, 0);
      if (!m) continue;
      int n = mj_sizeModel(m);
      mjVFS* vfs = malloc(sizeof(mjVFS));
      mj_defaultVFS(vfs);
      mj_makeEmptyFileVFS(vfs, "m.mjb", n);
      void* buf = vfs->filedata[vfs->nfile - 1];
      mj_saveModel(m, NULL, buf, n);
      last_warning[0] = 0;
      mjModel* m2 = mj_loadModel("m.mjb", vfs);
      if (!m2) {
        printf("%s reject %s\n", argv[f], last_warning);
      } else {
        void* buf2 = calloc(n, 1);
        mj_saveModel(m2, NULL, buf2, n);
        printf("%s %s\n", argv[f], memcmp(buf, buf2, n) ? "differs" : "same");
        free(buf2);
        mj_deleteModel(m2);
      }
      mj_deleteVFS(vfs);
      free(vfs);
      mj_deleteModel(m);
      fflush(stdout);
    }
    return 0;
  }
  if (argc == 3 && !strcmp(argv[1], "step")) {  // one file, in this process (for a debugger)
    cur_vfs = 0;
    snprintf(cur_path, sizeof cur_path, "%s", argv[2]);
    load_and_step("");
    return 0;
  }
  if (argc == 3 && !strcmp(argv[1], "probe")) {
    size_t n;
    unsigned char* orig = read_all(argv[2], &n);
    if (!orig) return 1;
    cur = malloc(n + 64);
    for (int vfs = 0; vfs < 2; vfs++) {
      memcpy(cur, orig, n);
      memset(cur + n, 0, 64);
      cur_size = n;
      run_case(0, "as-saved", vfs);
      cur_size = n + 64;
      run_case(1, "trailing-64", vfs);
      cur_size = n + 1;
      run_case(2, "trailing-1", vfs);
      cur_size = n - 1;
      run_case(3, "short-1", vfs);
      cur_size = 10;
      run_case(4, "short-header", vfs);
      cur_size = 16 + 8;
      run_case(5, "short-ints", vfs);
      cur_size = n;
      int bad = 12345;
      memcpy(cur, &bad, 4);
      run_case(6, "bad-id", vfs);
      memcpy(cur, orig, 4);
      memcpy(cur + 4, &bad, 4);
      run_case(7, "bad-precision", vfs);
    }
    remove(cur_path);
    return 0;
  }
  fprintf(stderr, "usage: mjb_hostile save IN.xml OUT.mjb | mutants SEED N FILE... | roundtrip FILE.xml... | probe FILE\n");
  return 2;
}
