#pragma once
/// \file
/// What an MPI launcher (mpirun, mpiexec, srun) tells a process through its environment, read
/// without initialising MPI: whether this process is one rank of a launched job, and which.

namespace raylab::dist {

/// Whether an MPI launcher started this process (OpenMPI's, MPICH's or Slurm's variables).
bool launched_by_mpi();

/// This process's rank as the launcher's environment says (0 when not launched by one).
int launcher_rank();

/// Whether this build can render across MPI ranks (MPI was found when it was configured).
bool mpi_available();

/// Throws UsageError when this build has no MPI (for a process an MPI launcher started: it cannot
/// take its part in the job).
void require_mpi_build();

}  // namespace raylab::dist
