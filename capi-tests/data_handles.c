// mjData handled every way a program may (tests/data_handles.rs): copies made and copied
// into, a model copy used with the same data, a struct copied by value, data freed and made
// again, resets. Prints a hash of the state after each, identical on both libraries, of the
// whole array buffer after resets (fresh data, pages written here and there, all of it), and
// whether copies of fresh, written and stepped data equal their source byte for byte.
#include <mujoco/mjxmacro.h>
#include <mujoco/mujoco.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static uint64_t hash(uint64_t h, const void* p, size_t n) {
  const unsigned char* b = p;
  for (size_t i = 0; i < n; i++) h = (h ^ b[i]) * 1099511628211ull;
  return h;
}

static void show(const char* what, const mjModel* m, const mjData* d) {
  uint64_t h = 14695981039346656037ull;
  h = hash(h, &d->time, sizeof d->time);
  h = hash(h, d->qpos, sizeof(mjtNum) * m->nq);
  h = hash(h, d->qvel, sizeof(mjtNum) * m->nv);
  h = hash(h, d->qacc, sizeof(mjtNum) * m->nv);
  h = hash(h, d->efc_force, sizeof(mjtNum) * d->nefc);
  printf("%-28s ncon %3d nefc %3d maxuse_stack %6d hash %016llx\n", what, d->ncon, d->nefc,
         d->maxuse_stack, (unsigned long long)h);
}

// The whole buffer after mj_resetData: arrays and the padding between them are zeros but
// for the state the reset sets, written pages and never touched ones alike.
static void show_buffer(const char* what, const mjModel* m, mjData* d) {
  mj_resetData(m, d);
  printf("%-28s nbuffer %8d hash %016llx\n", what, d->nbuffer,
         (unsigned long long)hash(14695981039346656037ull, d->buffer, d->nbuffer));
}

static void steps(const mjModel* m, mjData* d, int n);

// mj_copyData copies every array (2.2.2 leaves the padding between them): whether each of
// dst's arrays equals src's byte for byte after it, and a hash of dst's whole buffer when src
// is fresh data (the same bytes on both libraries).
static void show_copy(const char* what, const mjModel* m, mjData* dst, const mjData* src,
                      int fresh) {
  mj_copyData(dst, m, src);
  int same = 1;
  MJDATA_POINTERS_PREAMBLE(m)
#define X(type, name, nr, nc) \
  same &= !memcmp(dst->name, src->name, sizeof(type) * (m->nr) * (nc));
  MJDATA_POINTERS
#undef X
  printf("%-28s nbuffer %8d copy %s", what, src->nbuffer, same ? "equal" : "DIFFERS");
  if (fresh) {
    uint64_t h = hash(14695981039346656037ull, dst->buffer, dst->nbuffer);
    printf(" hash %016llx", (unsigned long long)h);
  }
  printf("\n");
}

static void buffer_resets(const mjModel* m) {
  // copies: fresh data over data written all over, stepped data into fresh data, fresh into
  // fresh
  mjData* fresh = mj_makeData(m);
  mjData* written = mj_makeData(m);
  memset(written->buffer, 0x5a, written->nbuffer);
  show_copy("fresh over written, copy", m, written, fresh, 1);
  mjData* other = mj_makeData(m);
  show_copy("fresh into fresh, copy", m, other, fresh, 1);
  steps(m, fresh, 20);
  show_copy("stepped into fresh, copy", m, other, fresh, 0);
  memset(other->buffer, 0x5a, other->nbuffer);
  show_copy("stepped over written, copy", m, other, fresh, 0);
  show_copy("onto itself, copy", m, other, other, 0);
  mj_deleteData(other);
  mj_deleteData(written);
  mj_deleteData(fresh);

  mjData* d = mj_makeData(m);
  show_buffer("fresh, reset", m, d);
  // a page in three written, the last bytes spilling into the next page
  size_t n = d->nbuffer, page = 4096;
  for (size_t at = 0; at < n; at += 3 * page) {
    memset((char*)d->buffer + at, 0xa5, n - at < page + 100 ? n - at : page + 100);
  }
  show_buffer("a page in three, reset", m, d);
  memset(d->buffer, 0x5a, n);
  show_buffer("all written, reset", m, d);
  mj_deleteData(d);
}

static void steps(const mjModel* m, mjData* d, int n) {
  for (int i = 0; i < n; i++) {
    if (m->nu) d->ctrl[0] = 0.3;
    mj_step(m, d);
  }
}

int main(int argc, char** argv) {
  char err[1000] = "";
  for (int f = 1; f < argc; f++) {
    mjModel* m = mj_loadXML(argv[f], NULL, err, sizeof err);
    if (!m) {
      printf("error: %s\n", err);
      return 1;
    }
    printf("%s\n", strrchr(argv[f], '/') ? strrchr(argv[f], '/') + 1 : argv[f]);
    mjData* d1 = mj_makeData(m);
    steps(m, d1, 100);
    show("made, 100 steps", m, d1);

    mjData* d2 = mj_copyData(NULL, m, d1);
    steps(m, d2, 50);
    steps(m, d1, 50);
    show("copy, 50 steps", m, d2);
    show("original, 50 steps", m, d1);

    mj_copyData(d1, m, d2);  // into existing data
    steps(m, d1, 20);
    show("copied into, 20 steps", m, d1);

    mjModel* m2 = mj_copyModel(NULL, m);
    for (int i = 0; i < 30; i++) steps(i % 2 ? m2 : m, d1, 1);
    show("model and its copy", m, d1);

    mjData byvalue = *d1;  // a struct copy: the same arrays
    steps(m, &byvalue, 10);
    show("struct copy, 10 steps", m, &byvalue);
    steps(m, d1, 10);
    show("then original, 10 steps", m, d1);

    mj_deleteData(d2);
    mj_deleteData(d1);
    d1 = mj_makeData(m2);  // likely where the last one was
    steps(m2, d1, 40);
    show("made again, 40 steps", m2, d1);

    mj_resetData(m2, d1);
    mj_forward(m2, d1);
    show("reset, forward", m2, d1);
    if (m2->nkey) mj_resetDataKeyframe(m2, d1, 0);
    steps(m2, d1, 25);
    show("keyframe, 25 steps", m2, d1);

    mj_deleteData(d1);
    buffer_resets(m2);
    mj_deleteModel(m2);
    mj_deleteModel(m);
  }
  return 0;
}
