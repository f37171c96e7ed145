/* The C interface between bladebench and its PETSc/SLEPc plugin (libbladebench_slepc.so).
   The plugin is loaded at run time into a symbol scope of its own: PETSc links the MPI build of
   MUMPS, bladebench's Sturm counts the sequential one (itself a module, linalg/mumps_module), and
   the two define the same symbols. Nothing but
   plain C types crosses this line; arrays the plugin allocates are released by bb_plugin_free. */
#ifndef BLADEBENCH_DISTRIBUTED_PLUGIN_ABI_H
#define BLADEBENCH_DISTRIBUTED_PLUGIN_ABI_H
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define BB_PLUGIN_ABI_VERSION 4

/* Upper triangle (column >= row) of a symmetric matrix, row by row, on every rank whole. */
typedef struct {
  int64_t n;
  const int64_t* row_start; /* n + 1 */
  const int64_t* column;
  const double* value;
} bb_upper_csr;

typedef struct {
  int world;          /* 1: the solve is shared by every rank (PETSC_COMM_WORLD); 0: this rank alone */
  double lower;       /* interval [lower, upper] of eigenvalues (rad^2/s^2); K - lower M must be positive definite */
  double upper;
  int n_estimate;     /* > 0: no slicing; the n eigenvalues nearest `lower` by shift-invert (estimates of a band top) */
  double tolerance;   /* relative residual */
  int max_iterations;
  int out_of_core;    /* 1: MUMPS keeps its factors on disk (ICNTL(22) = 1) */
} bb_modes_request;

typedef struct {
  int count;              /* eigenpairs returned, ascending */
  int64_t n;              /* rows of each vector */
  double* eigenvalues;    /* count */
  double* vectors;        /* n x count, column-major, on every rank */
  int shifts;             /* slicing: the shifts factorized and the inertia (eigenvalues below) at each */
  double* shift_values;
  int* inertias;
  int iterations;
  double seconds;
} bb_modes_result;

/* solve_spd's status when A is singular or indefinite: the caller's input, not a solver failure. */
#define BB_NOT_POSITIVE_DEFINITE 2

typedef struct {
  int abi_version;
  /* MPI and PETSc/SLEPc started (MPI_Init when nobody has); 0 on success. */
  int (*initialize)(char* message, size_t message_size);
  void (*finalize)(void);
  int (*rank)(void);
  int (*size)(void);
  /* Every rank's values combined by max, in place. */
  int (*allreduce_max)(int* values, int count);
  int (*barrier)(void);
  /* Every rank's byte count (all: size() entries), then every rank's bytes in rank order (all: their sum). */
  int (*allgather_sizes)(int64_t mine, int64_t* all);
  int (*allgather_bytes)(const char* mine, int64_t mine_size, const int64_t* sizes, char* all);
  void (*abort_all)(int exit_code);
  /* Bytes to one rank without waiting for their receipt (the plugin keeps a copy until complete_sends). */
  int (*send_bytes)(int to, int tag, const char* bytes, int64_t size);
  /* The size of the next message from `from` with `tag` (waits for it), then the message itself. */
  int (*probe_bytes)(int from, int tag, int64_t* size);
  int (*receive_bytes)(int from, int tag, char* bytes, int64_t size);
  /* Waits until every message this rank sent has been received. */
  int (*complete_sends)(void);
  /* 0 on success; otherwise the message says why (PETSc's error text, or a count that disagrees). */
  int (*modes)(const bb_upper_csr* stiffness, const bb_upper_csr* mass, const bb_modes_request* request,
               bb_modes_result* result, char* message, size_t message_size);
  /* X = A^{-1} B for symmetric positive definite A (MUMPS Cholesky), B and X n x columns column-major;
     BB_NOT_POSITIVE_DEFINITE when A has a null or negative pivot (every rank returns it). */
  int (*solve_spd)(const bb_upper_csr* a, const double* b, int64_t columns, int world, double* x, char* message,
                   size_t message_size);
  void (*free_result)(bb_modes_result* result);
} bb_plugin;

/* The one symbol the loader looks up. */
const bb_plugin* bladebench_plugin(void);

#ifdef __cplusplus
}
#endif
#endif
