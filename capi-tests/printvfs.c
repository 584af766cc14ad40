// mj_printModel, mj_printData and the VFS, run the same way on both libraries.
//   printvfs print MODEL OUTDIR   writes OUTDIR/model.txt and OUTDIR/data.txt after 50 steps
//   printvfs vfs MODEL OUTDIR     loads MODEL and the files beside it (meshes, textures...)
//                                 from a VFS only (OUTDIR absolute), prints the model to
//                                 OUTDIR/vfs_model.txt; exercises add/find/delete/empty files
//                                 and prints their codes. 2.2.2 reads the file name relative to
//                                 the working directory and ignores the directory argument.
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <dirent.h>
#include <unistd.h>
#include <mujoco/mujoco.h>

static int print(const char* model, const char* out) {
  char err[1000] = "";
  mjModel* m = mj_loadXML(model, NULL, err, sizeof(err));
  if (!m) {
    printf("load failed: %s\n", err);
    return 1;
  }
  mjData* d = mj_makeData(m);
  for (int i = 0; i < m->nu; i++) d->ctrl[i] = 0.3 * (i % 3 - 1);
  for (int i = 0; i < 50; i++) mj_step(m, d);
  char path[2000];
  snprintf(path, sizeof(path), "%s/model.txt", out);
  mj_printModel(m, path);
  snprintf(path, sizeof(path), "%s/data.txt", out);
  mj_printData(m, d, path);
  mj_deleteData(d);
  mj_deleteModel(m);
  printf("printed\n");
  return 0;
}

static int vfs(const char* model, const char* out) {
  mjVFS* v = malloc(sizeof(mjVFS));
  mj_defaultVFS(v);
  // the model's directory: every regular file goes into the VFS under its own name
  char dir[1000];
  strncpy(dir, model, sizeof(dir) - 1);
  dir[sizeof(dir) - 1] = 0;
  char* slash = strrchr(dir, '/');
  const char* base = model;
  if (slash) {
    slash[1] = 0;  // the directory keeps its separator: 2.2.2 joins directory and file as is
    base = strrchr(model, '/') + 1;
  } else {
    strcpy(dir, "./");
  }
  printf("from elsewhere %d\n", mj_addFileVFS(v, dir, base));
  if (chdir(dir)) {
    printf("chdir failed\n");
    return 1;
  }
  DIR* dd = opendir(".");
  struct dirent* e;
  int added = 0;
  while (dd && (e = readdir(dd))) {
    if (e->d_name[0] == '.') continue;
    int r = mj_addFileVFS(v, "ignored/", e->d_name);
    if (r == 0) added++;
  }
  if (dd) closedir(dd);
  printf("added %d files, nfile %d\n", added, v->nfile);
  int found = mj_findFileVFS(v, base) >= 0;
  int missing = mj_findFileVFS(v, "no-such-file.xml");
  printf("find model %d, find missing %d\n", found, missing);
  printf("add again %d\n", mj_addFileVFS(v, dir, base));
  int empty = mj_makeEmptyFileVFS(v, "empty.bin", 10);
  int again = mj_makeEmptyFileVFS(v, "empty.bin", 10);
  printf("empty file %d, again %d, nfile %d\n", empty, again, v->nfile);
  int del = mj_deleteFileVFS(v, "empty.bin");
  int del2 = mj_deleteFileVFS(v, "empty.bin");
  printf("delete %d, delete again %d, nfile %d\n", del, del2, v->nfile);
  char err[1000] = "";
  mjModel* m = mj_loadXML(base, v, err, sizeof(err));
  if (!m) {
    printf("vfs load failed: %s\n", err);
  } else {
    char path[2000];
    snprintf(path, sizeof(path), "%s/vfs_model.txt", out);
    mj_printModel(m, path);
    printf("vfs load nbody %d ngeom %d nmesh %d\n", m->nbody, m->ngeom, m->nmesh);
    mj_deleteModel(m);
  }
  mj_deleteVFS(v);
  free(v);
  return 0;
}

int main(int argc, char** argv) {
  if (argc == 4 && !strcmp(argv[1], "print")) return print(argv[2], argv[3]);
  if (argc == 4 && !strcmp(argv[1], "vfs")) return vfs(argv[2], argv[3]);
  fprintf(stderr, "usage: printvfs print|vfs MODEL OUTDIR\n");
  return 2;
}
