/* The cost of one MPI exchange (Irecv, Send, Wait) between 2 ranks, as
   LAMMPS makes them in a ghost swap, for 8 B to 50 kB (doc/studies/two-rank-comm.md,
   "Where the 2-rank Comm time goes").  GPL-2.0, part of GRFLOW.
     mpicc -O2 bench/mpi_exchange.c -o mpi_exchange
     mpirun --allow-run-as-root --oversubscribe -np 2 ./mpi_exchange */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
int main(int argc, char **argv) {
  MPI_Init(&argc, &argv);
  int me; MPI_Comm_rank(MPI_COMM_WORLD, &me);
  int sizes[] = {8, 800, 8000, 50000};
  for (int s = 0; s < 4; s++) {
    int n = sizes[s]; char *buf = calloc(n, 1); char *rb = calloc(n, 1);
    int other = 1 - me; int reps = 20000;
    MPI_Barrier(MPI_COMM_WORLD);
    double t0 = MPI_Wtime();
    for (int r = 0; r < reps; r++) {
      MPI_Request req;
      MPI_Irecv(rb, n, MPI_CHAR, other, 0, MPI_COMM_WORLD, &req);
      MPI_Send(buf, n, MPI_CHAR, other, 0, MPI_COMM_WORLD);
      MPI_Wait(&req, MPI_STATUS_IGNORE);
    }
    double t = (MPI_Wtime() - t0) / reps;
    if (me == 0) printf("exchange of %d bytes: %.2f us\n", n, t * 1e6);
    free(buf); free(rb);
  }
  MPI_Finalize();
}
