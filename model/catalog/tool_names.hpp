// Human-readable names and kinds for the tool and surface ids used in the paper's file names
// (see ../shared/data/piovarci2018/PROVENANCE.md, "Naming"), so catalogs and plots say "2H pencil"
// rather than "p2h". Unknown ids are kept as they are: a new tool never fails the pipeline.
#pragma once

#include <string>

#include "model/io/catalog_file.hpp"

namespace nibrig::model::catalog {

// Builds the catalog entry of a tool id such as "p2h", "vero1", "DM852", "apencil", "penh_DM85",
// or a lab's one-material print "<material>-<tip>mm" such as "PLA-1mm".
io::ToolEntry describe_tool(const std::string& tool_id);

io::SurfaceEntry describe_surface(const std::string& surface_id);

}  // namespace nibrig::model::catalog
