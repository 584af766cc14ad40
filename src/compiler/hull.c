/* Convex hull of a point set through qhull, returned as plain arrays for src/compiler/hull.rs.
   Runs qhull the way MuJoCo 2.2.2 does for mesh graphs: options "Qt", triangulated output,
   vertex neighbours; qhull errors come back as a status instead of a longjmp into Rust. */

#include <setjmp.h>
#include <stdlib.h>
#include <stdio.h>
#include "libqhull_r/qhull_ra.h"

typedef struct {
  int numvert;     /* hull vertices, in qhull's vertex list order */
  int numface;     /* triangles, in qhull's facet list order */
  int* vert_point; /* numvert: input point index of each vertex */
  int* nbr_adr;    /* numvert+1: start of each vertex's facets in nbr */
  int* nbr;        /* facet indices, in each vertex's neighbour-set order */
  int* face_point; /* 3*numface: input point index of each facet vertex, in set order */
  int* face_top;   /* numface: facet toporient flag */
} rj_hull;

void rj_hull_free(rj_hull* h) {
  free(h->vert_point);
  free(h->nbr_adr);
  free(h->nbr);
  free(h->face_point);
  free(h->face_top);
  h->vert_point = h->nbr_adr = h->nbr = h->face_point = h->face_top = NULL;
}

/* 0: done; 1: qhull error; 2: a facet is not a triangle; 3: out of memory */
int rj_hull_build(double* points, int npoint, rj_hull* out) {
  qhT qh_qh;
  qhT* qh = &qh_qh;
  facetT *facet, *neighbor, **neighborp;
  vertexT *vertex, **vertexp;
  int curlong, totlong, status = 0;
  char options[] = "qhull Qt";

  out->numvert = out->numface = 0;
  out->vert_point = out->nbr_adr = out->nbr = out->face_point = out->face_top = NULL;
  qh_zero(qh, stderr);
  qh_init_A(qh, stdin, stdout, stderr, 0, NULL);
  if (setjmp(qh->errexit)) {
    status = 1;
  } else {
    qh->NOerrexit = False;
    qh_initflags(qh, options);
    qh_init_B(qh, points, npoint, 3, False);
    qh_qhull(qh);
    qh_triangulate(qh);
    qh_vertexneighbors(qh);

    int nv = qh->num_vertices, nf = qh->num_facets, nnbr = 0, k = 0;
    FORALLvertices nnbr += qh_setsize(qh, vertex->neighbors);
    out->vert_point = malloc(sizeof(int) * (nv > 0 ? nv : 1));
    out->nbr_adr = malloc(sizeof(int) * (nv + 1));
    out->nbr = malloc(sizeof(int) * (nnbr > 0 ? nnbr : 1));
    out->face_point = malloc(sizeof(int) * (3 * nf > 0 ? 3 * nf : 1));
    out->face_top = malloc(sizeof(int) * (nf > 0 ? nf : 1));
    if (!out->vert_point || !out->nbr_adr || !out->nbr || !out->face_point || !out->face_top) {
      status = 3;
    } else {
      /* number the facets in list order (visitid is free once the hull is built) */
      FORALLfacets {
        if (k >= nf || qh_setsize(qh, facet->vertices) != 3) {
          status = 2;
          break;
        }
        facet->visitid = (unsigned int)k;
        out->face_top[k] = facet->toporient ? 1 : 0;
        int j = 0;
        FOREACHvertex_(facet->vertices) out->face_point[3 * k + j++] = qh_pointid(qh, vertex->point);
        k++;
      }
      if (!status && k == nf) {
        int i = 0, adr = 0;
        FORALLvertices {
          out->vert_point[i] = qh_pointid(qh, vertex->point);
          out->nbr_adr[i] = adr;
          FOREACHneighbor_(vertex) out->nbr[adr++] = (int)neighbor->visitid;
          i++;
        }
        out->nbr_adr[i] = adr;
        out->numvert = nv;
        out->numface = nf;
      } else if (!status) {
        status = 2;
      }
    }
  }
  qh->NOerrexit = True;
  qh_freeqhull(qh, !qh_ALL);
  qh_memfreeshort(qh, &curlong, &totlong);
  if (status) {
    rj_hull_free(out);
  }
  return status;
}
