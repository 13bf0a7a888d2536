// From a tool catalog to the exemplars of the forcing fit: which measured pairings are printed
// tools with a design (material × tip diameter), their simulated responses |H| (one FEM model per
// distinct design, computed once), and which of them are the paper's 27 tools.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "model/forcing/forcing_fit.hpp"
#include "model/io/catalog_file.hpp"
#include "model/mechanics/stylus_description.hpp"

namespace nibrig::model::forcing {

struct ExemplarSelection {
  std::vector<ForcingExemplar> exemplars;  // responses still empty; catalog order
  // Pairings of printed tools left out, each with the reason ("DM851_nail1 on note: ..."). Tools
  // of other kinds (real, commercial) have no design and are only counted.
  std::vector<std::string> excluded;
  std::size_t other_kinds = 0;
};

// A pairing is an exemplar when its tool is "printed", has a material with a design
// (printed_tip_of: the paper's, or with `materials` also any of that table printed whole) and a tip
// diameter, is not a variant (an id with "_nail": the same print worn by a nail test, no design of
// its own), and the pairing has a vibration spectrum. The pen-holder prints (penh_*) have no tip
// diameter.
ExemplarSelection select_printed_exemplars(const io::Catalog& catalog,
                                           const mechanics::MaterialTable* materials = nullptr);

// The paper's 27 tools: {vero, DM95, DM85} × {1, 2, 4 mm} × {office, note, stone} (Sec. 5.2).
bool is_paper_tool(const ForcingExemplar& exemplar);
// Those of the 27 that `exemplars` lack, as "DM852 on office" (the bundled catalog lacks four:
// their recordings were not in the data snapshot).
std::vector<std::string> missing_paper_tools(const std::vector<ForcingExemplar>& exemplars);

struct ResponseOptions {
  double mesh_size = 0.0;  // m; 0 keeps the template's
  int modes = 0;           // 0 keeps the template's
};

struct DesignResponse {
  std::string design;                // mechanics::Design::name
  std::vector<std::string> used_by;  // catalog materials × tips, e.g. "vero 2 mm"
  std::size_t modes = 0;
  double first_mode_hz = 0.0;
  double seconds = 0.0;
};

// Fills every exemplar's response_magnitude with |H| of its printed_tool_design (from
// `template_design`) at its frequencies: each distinct design is meshed and solved once (tools of
// materials that share a design, like vero and teflon, share it). `progress`, when given, is called
// after each design with how many are done of how many. Returns what was computed, in order. Throws
// what build_design_model throws, and std::invalid_argument for an exemplar whose material has no
// design.
std::vector<DesignResponse> attach_responses(
    std::vector<ForcingExemplar>& exemplars, const mechanics::Design& template_design,
    const mechanics::MaterialTable& materials, const ResponseOptions& options = {},
    const std::function<void(const DesignResponse&, std::size_t done, std::size_t total)>&
        progress = {});

}  // namespace nibrig::model::forcing
