#pragma once

namespace glint::app {

/// True when an MPI launcher started this process: Open MPI's mpirun, or a PMI/PMIx
/// launcher (Slurm's srun, MPICH's Hydra).
[[nodiscard]] bool launched_by_mpi();

}  // namespace glint::app
