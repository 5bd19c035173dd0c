#include "mpi_launcher.h"

#include <cstdlib>
#include <initializer_list>

namespace glint::app {

bool launched_by_mpi() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
        if (std::getenv(name) != nullptr) return true;
    return false;
}

}  // namespace glint::app
