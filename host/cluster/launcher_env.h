// How many processes an MPI launcher says it started, from the environment it sets:
// Open MPI's OMPI_COMM_WORLD_SIZE, or MPICH's PMI_SIZE (also Slurm's srun --mpi=pmi2);
// 1 when neither is set. Read before MPI_Init, so that a process run alone never initialises MPI.
#pragma once

namespace vkpt::internal {

int LauncherProcessCount();

}  // namespace vkpt::internal
