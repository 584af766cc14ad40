// Inputs at the edge of the shortcuts that leave out work whose result cannot change 2.2.2's
// (tests/shortcuts.rs runs it on both libraries; the outputs must be identical):
//   free and ball joints without stiffness skip the quaternion difference of their spring
//   where positions and spring positions are finite; with a NaN, an infinity or a huge value
//   in qpos or qpos_spring, qfrc_passive must still be 2.2.2's, bit for bit.
// Prints, per case, mj_forward's qfrc_passive and qacc as hexadecimal bit patterns, a NaN as
// "nan" (its sign and payload follow the operand order a C compiler picks, as in the parity
// tests).
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <mujoco/mujoco.h>

static const char* xml =
    "<mujoco><option><flag contact='disable'/></option><worldbody>"
    "<body name='free0' pos='0 0 1'><freejoint/><geom size='.1' mass='1'/></body>"
    "<body name='free1' pos='1 0 1'><joint type='free' stiffness='2'/><geom size='.1'/></body>"
    "<body name='ball' pos='0 1 1'><joint type='ball' damping='.1'/>"
    "<geom type='capsule' fromto='0 0 0 .2 0 0' size='.05'/></body>"
    "</worldbody></mujoco>";

static void print_bits(const char* label, const mjtNum* x, int n) {
  printf("%s", label);
  for (int i = 0; i < n; i++) {
    if (isnan(x[i])) {
      printf(" nan");
      continue;
    }
    uint64_t b;
    memcpy(&b, &x[i], sizeof b);
    printf(" %016llx", (unsigned long long)b);
  }
  printf("\n");
}

int main(void) {
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  mj_makeEmptyFileVFS(&vfs, "s.xml", (int)strlen(xml));
  memcpy(vfs.filedata[0], xml, strlen(xml));
  char err[500] = "";
  mjModel* m = mj_loadXML("s.xml", &vfs, err, sizeof err);
  if (!m) {
    printf("load error %s\n", err);
    return 1;
  }
  mjData* d = mj_makeData(m);
  const double bad[] = {NAN, INFINITY, -INFINITY, 1e300, -1e-320, 0.0, -0.0};
  const int nbad = sizeof bad / sizeof bad[0];
  int c = 0;
  for (int where = 0; where < 2; where++) {       // qpos, qpos_spring
    for (int adr = 0; adr < m->nq; adr++) {
      for (int k = 0; k < nbad; k++) {
        mj_resetData(m, d);
        for (int i = 0; i < m->nv; i++) d->qvel[i] = 0.1 * (i + 1);
        mjtNum* target = where ? m->qpos_spring : d->qpos;
        mjtNum keep = target[adr];
        target[adr] = bad[k];
        mj_forward(m, d);
        char label[64];
        snprintf(label, sizeof label, "case %d %s[%d]=%g passive", c++, where ? "spring" : "qpos",
                 adr, bad[k]);
        print_bits(label, d->qfrc_passive, m->nv);
        print_bits("  qacc", d->qacc, m->nv);
        target[adr] = keep;
      }
    }
  }
  mj_deleteData(d);
  mj_deleteModel(m);
  mj_deleteVFS(&vfs);
  return 0;
}
