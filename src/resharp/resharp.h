#pragma once
/// resharp: restores the sharp machined edges and corners that grid-based machining simulation
/// turns into chamfer bands. Include this header and call restore(); see pipeline/restore.h.

#include "resharp/core/errors.h"
#include "resharp/mesh/mesh.h"
#include "resharp/pipeline/options.h"
#include "resharp/pipeline/report.h"
#include "resharp/pipeline/restore.h"
