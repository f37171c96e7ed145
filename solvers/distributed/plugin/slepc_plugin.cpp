// bladebench's PETSc/SLEPc plugin: MPI start-up and collectives, spectrum slicing of K x = lambda M x
// (Krylov-Schur, shift-and-invert, MUMPS Cholesky whose inertias count the eigenvalues), and SPD
// solves by MUMPS. Built as its own module so that PETSc's MPI MUMPS never meets the sequential one.
#include <slepceps.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <list>
#include <string>
#include <vector>

#include "distributed/plugin_abi.h"

namespace {

std::string first_error;  // the message of the innermost failing PETSc call, for the caller

PetscErrorCode record_error(MPI_Comm, int line, const char* function, const char* file, PetscErrorCode code,
                            PetscErrorType type, const char* message, void*) {
  if (type == PETSC_ERROR_INITIAL) {
    const char* text = nullptr;
    PetscErrorMessage(code, &text, nullptr);
    first_error = std::string(message && *message ? message : (text ? text : "PETSc error")) + " (" + function +
                  " at " + file + ":" + std::to_string(line) + ")";
  }
  return code;
}

void say(char* out, size_t size, const std::string& text) {
  if (out && size > 0) std::snprintf(out, size, "%s", text.c_str());
}

// A PETSc call that fails ends the function with its message.
#define BB_TRY(call)                                                                      \
  do {                                                                                    \
    const PetscErrorCode bb_code = (call);                                                \
    if (bb_code) {                                                                        \
      say(message, message_size, first_error.empty() ? std::string(#call) : first_error); \
      first_error.clear();                                                                \
      return static_cast<int>(bb_code);                                                   \
    }                                                                                     \
  } while (0)

bool started_mpi = false;

int initialize(char* message, size_t message_size) {
  PetscBool done = PETSC_FALSE;
  PetscInitialized(&done);
  if (done) return 0;
  int mpi = 0;
  MPI_Initialized(&mpi);
  if (!mpi) {
    int provided = 0;
    if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
      say(message, message_size, "MPI_Init_thread failed");
      return 1;
    }
    started_mpi = true;
  }
  // bladebench keeps its own signal handling and reads no PETSc options from the command line.
  PetscOptionsSetValue(nullptr, "-no_signal_handler", nullptr);
  const PetscErrorCode code = SlepcInitializeNoArguments();
  if (code) {
    say(message, message_size, "SlepcInitialize failed");
    return static_cast<int>(code);
  }
  PetscPushErrorHandler(record_error, nullptr);
  // The factorization of every shift: MUMPS Cholesky (LDL^T with 2x2 pivots), whose inertia the
  // slicing reads; ICNTL(13) = 1 keeps the root node off ScaLAPACK, which would not give it.
  PetscOptionsInsertString(
      nullptr,
      "-bb_st_ksp_type preonly -bb_st_pc_type cholesky -bb_st_pc_factor_mat_solver_type mumps "
      "-bb_st_mat_mumps_icntl_13 1 -bb_spd_ksp_type preonly -bb_spd_pc_type cholesky "
      "-bb_spd_pc_factor_mat_solver_type mumps -bb_spd_mat_mumps_icntl_24 1 -bb_spd_mat_mumps_cntl_3 1e-12");
  return 0;
}

void finalize() {
  PetscBool done = PETSC_FALSE;
  PetscInitialized(&done);
  if (done) SlepcFinalize();
  int finished = 0;
  MPI_Finalized(&finished);
  if (started_mpi && !finished) MPI_Finalize();
}

int rank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int size() {
  int s = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &s);
  return s;
}

int allreduce_max(int* values, int count) {
  return MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_INT, MPI_MAX, MPI_COMM_WORLD) == MPI_SUCCESS ? 0 : 1;
}

int barrier() { return MPI_Barrier(MPI_COMM_WORLD) == MPI_SUCCESS ? 0 : 1; }

int allgather_sizes(int64_t mine, int64_t* all) {
  return MPI_Allgather(&mine, 1, MPI_INT64_T, all, 1, MPI_INT64_T, MPI_COMM_WORLD) == MPI_SUCCESS ? 0 : 1;
}

int allgather_bytes(const char* mine, int64_t mine_size, const int64_t* sizes, char* all) {
  const int ranks = size();
  std::vector<int> counts(static_cast<size_t>(ranks)), offsets(static_cast<size_t>(ranks));
  int64_t offset = 0;
  for (int r = 0; r < ranks; ++r) {
    if (sizes[r] > INT32_MAX || offset > INT32_MAX) return 1;  // MPI's counts are int
    counts[static_cast<size_t>(r)] = static_cast<int>(sizes[r]);
    offsets[static_cast<size_t>(r)] = static_cast<int>(offset);
    offset += sizes[r];
  }
  return MPI_Allgatherv(mine, static_cast<int>(mine_size), MPI_CHAR, all, counts.data(), offsets.data(), MPI_CHAR,
                        MPI_COMM_WORLD) == MPI_SUCCESS
             ? 0
             : 1;
}

void abort_all(int exit_code) { MPI_Abort(MPI_COMM_WORLD, exit_code); }

// Messages sent and not yet known to be received, with their bytes (std::list: the buffers stay put).
struct PendingSend {
  std::vector<char> bytes;
  MPI_Request request = MPI_REQUEST_NULL;
};
std::list<PendingSend>& pending_sends() {
  static std::list<PendingSend> pending;
  return pending;
}

int send_bytes(int to, int tag, const char* bytes, int64_t size) {
  if (size > INT32_MAX) return 1;  // MPI's counts are int
  PendingSend& s = pending_sends().emplace_back();
  s.bytes.assign(bytes, bytes + size);
  return MPI_Isend(s.bytes.data(), static_cast<int>(size), MPI_CHAR, to, tag, MPI_COMM_WORLD, &s.request) == MPI_SUCCESS
             ? 0
             : 1;
}

int probe_bytes(int from, int tag, int64_t* size) {
  MPI_Status status;
  if (MPI_Probe(from, tag, MPI_COMM_WORLD, &status) != MPI_SUCCESS) return 1;
  int count = 0;
  if (MPI_Get_count(&status, MPI_CHAR, &count) != MPI_SUCCESS) return 1;
  *size = count;
  return 0;
}

int receive_bytes(int from, int tag, char* bytes, int64_t size) {
  if (size > INT32_MAX) return 1;
  return MPI_Recv(bytes, static_cast<int>(size), MPI_CHAR, from, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE) == MPI_SUCCESS
             ? 0
             : 1;
}

int complete_sends() {
  int failed = 0;
  for (PendingSend& s : pending_sends())
    if (MPI_Wait(&s.request, MPI_STATUS_IGNORE) != MPI_SUCCESS) failed = 1;
  pending_sends().clear();
  return failed;
}

// PETSc's default row split: the first n % p ranks take one row more.
void owned_rows(MPI_Comm comm, int64_t n, int64_t* first, int64_t* count) {
  int r = 0, p = 1;
  MPI_Comm_rank(comm, &r);
  MPI_Comm_size(comm, &p);
  const int64_t base = n / p, extra = n % p;
  *count = base + (r < extra ? 1 : 0);
  *first = r * base + std::min<int64_t>(r, extra);
}

// The rows this rank owns, as a symmetric block matrix of block size 1 (upper triangle stored).
PetscErrorCode make_matrix(MPI_Comm comm, const bb_upper_csr* a, Mat* out) {
  int64_t first = 0, count = 0;
  owned_rows(comm, a->n, &first, &count);
  std::vector<PetscInt> starts(static_cast<size_t>(count) + 1), columns;
  const int64_t offset = a->row_start[first];
  for (int64_t i = 0; i <= count; ++i)
    starts[static_cast<size_t>(i)] = static_cast<PetscInt>(a->row_start[first + i] - offset);
  const int64_t nnz = a->row_start[first + count] - offset;
  columns.resize(static_cast<size_t>(nnz));
  for (int64_t k = 0; k < nnz; ++k) columns[static_cast<size_t>(k)] = static_cast<PetscInt>(a->column[offset + k]);
  const PetscScalar* values = a->value + offset;
  PetscCall(MatCreate(comm, out));
  PetscCall(MatSetSizes(*out, static_cast<PetscInt>(count), static_cast<PetscInt>(count), static_cast<PetscInt>(a->n),
                        static_cast<PetscInt>(a->n)));
  PetscCall(MatSetType(*out, MATSBAIJ));
  PetscCall(MatSeqSBAIJSetPreallocationCSR(*out, 1, starts.data(), columns.data(), values));
  PetscCall(MatMPISBAIJSetPreallocationCSR(*out, 1, starts.data(), columns.data(), values));
  PetscCall(MatSetOption(*out, MAT_SYMMETRIC, PETSC_TRUE));
  PetscFunctionReturn(0);
}

// x whole on every rank.
PetscErrorCode gather(Vec x, double* out) {
  VecScatter scatter;
  Vec all;
  PetscCall(VecScatterCreateToAll(x, &scatter, &all));
  PetscCall(VecScatterBegin(scatter, x, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(scatter, x, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscInt n = 0;
  PetscCall(VecGetSize(all, &n));
  const PetscScalar* v = nullptr;
  PetscCall(VecGetArrayRead(all, &v));
  std::copy(v, v + n, out);
  PetscCall(VecRestoreArrayRead(all, &v));
  PetscCall(VecScatterDestroy(&scatter));
  PetscCall(VecDestroy(&all));
  PetscFunctionReturn(0);
}

int modes(const bb_upper_csr* stiffness, const bb_upper_csr* mass, const bb_modes_request* request,
          bb_modes_result* result, char* message, size_t message_size) {
  *result = bb_modes_result{};
  const MPI_Comm comm = request->world ? PETSC_COMM_WORLD : PETSC_COMM_SELF;
  const double t0 = MPI_Wtime();
  Mat k = nullptr, m = nullptr;
  BB_TRY(make_matrix(comm, stiffness, &k));
  BB_TRY(make_matrix(comm, mass, &m));
  EPS eps = nullptr;
  BB_TRY(EPSCreate(comm, &eps));
  BB_TRY(EPSSetOptionsPrefix(eps, "bb_"));
  BB_TRY(EPSSetOperators(eps, k, m));
  BB_TRY(EPSSetProblemType(eps, EPS_GHEP));
  BB_TRY(EPSSetType(eps, EPSKRYLOVSCHUR));
  ST st = nullptr;
  BB_TRY(EPSGetST(eps, &st));
  BB_TRY(STSetType(st, STSINVERT));
  const bool slicing = request->n_estimate <= 0;
  if (slicing) {
    BB_TRY(EPSSetWhichEigenpairs(eps, EPS_ALL));
    BB_TRY(EPSSetInterval(eps, request->lower, request->upper));
  } else {
    BB_TRY(EPSSetWhichEigenpairs(eps, EPS_TARGET_MAGNITUDE));
    BB_TRY(EPSSetTarget(eps, request->lower));
    BB_TRY(EPSSetDimensions(eps, request->n_estimate, PETSC_DEFAULT, PETSC_DEFAULT));
  }
  BB_TRY(EPSSetTolerances(eps, request->tolerance, request->max_iterations));
  // Purification (one more solve per vector) serves a singular M; with bladebench's positive
  // definite mass it cost Table VI's vectors two orders of backward error (3.4e-13 against 8.7e-16)
  // and 10 % of the time.
  BB_TRY(EPSSetPurify(eps, PETSC_FALSE));
  // Set on every call: the options database is global and outlives it; the case's out_of_core
  // decides, over any PETSC_OPTIONS value of the same option.
  BB_TRY(PetscOptionsSetValue(nullptr, "-bb_st_mat_mumps_icntl_22", request->out_of_core ? "1" : "0"));
  BB_TRY(EPSSetFromOptions(eps));
  BB_TRY(EPSSolve(eps));
  EPSConvergedReason reason;
  BB_TRY(EPSGetConvergedReason(eps, &reason));
  PetscInt converged = 0, iterations = 0;
  BB_TRY(EPSGetConverged(eps, &converged));
  BB_TRY(EPSGetIterationNumber(eps, &iterations));
  if (reason < 0 || (!slicing && converged < request->n_estimate)) {
    say(message, message_size,
        "Krylov-Schur stopped with " + std::to_string(converged) + " converged eigenpairs after " +
            std::to_string(iterations) + " iterations (reason " + std::to_string(static_cast<int>(reason)) + ")");
    EPSDestroy(&eps);
    MatDestroy(&k);
    MatDestroy(&m);
    return 1;
  }
  const PetscInt count = slicing ? converged : request->n_estimate;
  result->count = static_cast<int>(count);
  result->n = stiffness->n;
  result->iterations = static_cast<int>(iterations);
  result->eigenvalues =
      static_cast<double*>(std::malloc(sizeof(double) * static_cast<size_t>(std::max<PetscInt>(count, 1))));
  result->vectors = static_cast<double*>(
      std::malloc(sizeof(double) * static_cast<size_t>(std::max<int64_t>(stiffness->n * count, 1))));
  Vec x = nullptr;
  BB_TRY(MatCreateVecs(k, &x, nullptr));
  for (PetscInt i = 0; i < count; ++i) {
    PetscScalar lambda = 0;
    BB_TRY(EPSGetEigenpair(eps, i, &lambda, nullptr, x, nullptr));
    result->eigenvalues[i] = PetscRealPart(lambda);
    BB_TRY(gather(x, result->vectors + i * stiffness->n));
  }
  BB_TRY(VecDestroy(&x));
  if (slicing) {
    PetscInt shifts = 0;
    PetscReal* values = nullptr;
    PetscInt* inertias = nullptr;
    BB_TRY(EPSKrylovSchurGetInertias(eps, &shifts, &values, &inertias));
    result->shifts = static_cast<int>(shifts);
    result->shift_values =
        static_cast<double*>(std::malloc(sizeof(double) * static_cast<size_t>(std::max<PetscInt>(shifts, 1))));
    result->inertias = static_cast<int*>(std::malloc(sizeof(int) * static_cast<size_t>(std::max<PetscInt>(shifts, 1))));
    for (PetscInt i = 0; i < shifts; ++i) {
      result->shift_values[i] = values[i];
      result->inertias[i] = static_cast<int>(inertias[i]);
    }
    BB_TRY(PetscFree(values));
    BB_TRY(PetscFree(inertias));
  }
  BB_TRY(EPSDestroy(&eps));
  BB_TRY(MatDestroy(&k));
  BB_TRY(MatDestroy(&m));
  result->seconds = MPI_Wtime() - t0;
  return 0;
}

int solve_spd(const bb_upper_csr* a, const double* b, int64_t columns, int world, double* x_out, char* message,
              size_t message_size) {
  const MPI_Comm comm = world ? PETSC_COMM_WORLD : PETSC_COMM_SELF;
  Mat mat = nullptr;
  BB_TRY(make_matrix(comm, a, &mat));
  KSP ksp = nullptr;
  BB_TRY(KSPCreate(comm, &ksp));
  BB_TRY(KSPSetOptionsPrefix(ksp, "bb_spd_"));
  BB_TRY(KSPSetOperators(ksp, mat, mat));
  BB_TRY(KSPSetFromOptions(ksp));
  BB_TRY(KSPSetUp(ksp));
  // A singular or indefinite A would still factor (a tiny pivot, a large wrong solution): MUMPS's
  // null-pivot detection (ICNTL(24): a pivot under CNTL(3) = 1e-12 of the scaled matrix's norm; a
  // floating cantilever's null pivot measured 1e-14 to 1e-13, Table VIII's 88 k-DOF K_ss has none)
  // and its negative-pivot count (INFOG(28), INFOG(12)) refuse it.
  PC pc = nullptr;
  Mat factor = nullptr;
  PetscInt null_pivots = 0, negative_pivots = 0;
  BB_TRY(KSPGetPC(ksp, &pc));
  BB_TRY(PCFactorGetMatrix(pc, &factor));
  BB_TRY(MatMumpsGetInfog(factor, 28, &null_pivots));
  BB_TRY(MatMumpsGetInfog(factor, 12, &negative_pivots));
  if (null_pivots > 0 || negative_pivots > 0) {
    say(message, message_size,
        "the matrix is not positive definite: MUMPS found " + std::to_string(null_pivots) + " null and " +
            std::to_string(negative_pivots) + " negative pivots of " + std::to_string(a->n));
    KSPDestroy(&ksp);
    MatDestroy(&mat);
    return BB_NOT_POSITIVE_DEFINITE;
  }
  Vec rhs = nullptr, x = nullptr;
  BB_TRY(MatCreateVecs(mat, &x, &rhs));
  PetscInt first = 0, last = 0;
  BB_TRY(VecGetOwnershipRange(rhs, &first, &last));
  for (int64_t j = 0; j < columns; ++j) {
    PetscScalar* r = nullptr;
    BB_TRY(VecGetArray(rhs, &r));
    std::copy(b + j * a->n + first, b + j * a->n + last, r);
    BB_TRY(VecRestoreArray(rhs, &r));
    BB_TRY(KSPSolve(ksp, rhs, x));
    KSPConvergedReason reason;
    BB_TRY(KSPGetConvergedReason(ksp, &reason));
    if (reason < 0) {
      say(message, message_size,
          "MUMPS Cholesky solve failed (KSP reason " + std::to_string(static_cast<int>(reason)) + ")");
      return 1;
    }
    BB_TRY(gather(x, x_out + j * a->n));
  }
  BB_TRY(VecDestroy(&rhs));
  BB_TRY(VecDestroy(&x));
  BB_TRY(KSPDestroy(&ksp));
  BB_TRY(MatDestroy(&mat));
  return 0;
}

void free_result(bb_modes_result* r) {
  std::free(r->eigenvalues);
  std::free(r->vectors);
  std::free(r->shift_values);
  std::free(r->inertias);
  *r = bb_modes_result{};
}

const bb_plugin the_plugin = {.abi_version = BB_PLUGIN_ABI_VERSION,
                              .initialize = initialize,
                              .finalize = finalize,
                              .rank = rank,
                              .size = size,
                              .allreduce_max = allreduce_max,
                              .barrier = barrier,
                              .allgather_sizes = allgather_sizes,
                              .allgather_bytes = allgather_bytes,
                              .abort_all = abort_all,
                              .send_bytes = send_bytes,
                              .probe_bytes = probe_bytes,
                              .receive_bytes = receive_bytes,
                              .complete_sends = complete_sends,
                              .modes = modes,
                              .solve_spd = solve_spd,
                              .free_result = free_result};

}  // namespace

extern "C" const bb_plugin* bladebench_plugin(void) { return &the_plugin; }
