/**
 * @file mpi_exchange.cc
 * What one synchronisation between the ranks costs on this host when
 * neither waits for the other: a pairwise exchange of a message (the ghost
 * exchange's and the force compression's pattern) at a few sizes, and an
 * all-reduce of 4 doubles (the contact's and the wheelset's reductions).
 * Printed by './run.sh bench' beside the step's split, whose communication
 * and contact waiting it separates into this latency and the ranks waiting
 * for each other. Run on 2 ranks: mpirun -np 2 build/mpi_exchange
 */
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace
{
  /** Microseconds per call of @p f, best of 5 rounds of @p n calls. */
  template <typename F>
  double
  best_time(const unsigned int n, const F &f)
  {
    double best = 1e30;
    for (unsigned int round = 0; round < 5; ++round)
      {
        MPI_Barrier(MPI_COMM_WORLD);
        const double start = MPI_Wtime();
        for (unsigned int i = 0; i < n; ++i)
          f();
        double t = (MPI_Wtime() - start) / n;
        // the slower rank's time: a round ends when both have ended
        MPI_Allreduce(MPI_IN_PLACE, &t, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
        best = std::min(best, t);
      }
    return 1e6 * best;
  }
} // namespace

int
main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  int rank, n_ranks;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &n_ranks);
  if (n_ranks != 2)
    {
      if (rank == 0)
        std::fprintf(stderr, "mpi_exchange: run on 2 ranks (mpirun -np 2)\n");
      MPI_Finalize();
      return 1;
    }
  const int           other = 1 - rank;
  std::vector<double> send(16384, 1.), receive(16384);
  std::vector<double> times;
  const unsigned int  sizes[] = {8, 1024, 10240, 131072}; // bytes
  for (const unsigned int bytes : sizes)
    times.push_back(best_time(2000, [&] {
      MPI_Request requests[2];
      MPI_Irecv(receive.data(), bytes / 8, MPI_DOUBLE, other, 0, MPI_COMM_WORLD, &requests[0]);
      MPI_Isend(send.data(), bytes / 8, MPI_DOUBLE, other, 0, MPI_COMM_WORLD, &requests[1]);
      MPI_Waitall(2, requests, MPI_STATUSES_IGNORE);
    }));
  double values[4] = {1, 2, 3, 4};
  times.push_back(best_time(2000, [&] {
    MPI_Allreduce(MPI_IN_PLACE, values, 4, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  }));
  if (rank == 0)
    std::printf("MPI on 2 ranks (best of 5 x 2,000): exchange of 8 B %.2f us, 1 kB %.2f us, "
                "10 kB %.2f us, 128 kB %.2f us; all-reduce of 4 doubles %.2f us\n",
                times[0],
                times[1],
                times[2],
                times[3],
                times[4]);
  MPI_Finalize();
  return 0;
}
