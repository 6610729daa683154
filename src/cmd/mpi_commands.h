// quaternia-mpi's commands: `render` and `animate` with quaternia's options and scene keys,
// their work spread over the ranks of an MPI job (quaternia/distribute/work_scheduler.h) and
// their files byte for byte those of quaternia's commands.
#pragma once

#include "cmd/animate_command.h"
#include "cmd/render_command.h"
#include "quaternia/distribute/mpi_channel.h"

namespace quaternia {

// A poster (quaternia/film/poster.h): units handed out on demand, the PNG written by rank 0 as
// bands complete.
int runMpiRender(const MpiSession& mpi, const RenderCommandOptions& options);
// A film: frames handed out on demand, each written by the rank that rendered it; rank 0 encodes
// the video at the end.
int runMpiAnimate(const MpiSession& mpi, const AnimateCommandOptions& options);

}  // namespace quaternia
