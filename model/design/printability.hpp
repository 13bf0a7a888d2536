// Whether a printer can make a stylus, and if not why: a material it does not have, a mix on a
// printer that cannot mix, more materials than one print holds, a tip below its nozzle or a few
// of its pixels, a stylus larger than its build volume. Every face's export asks here once.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "model/design/stylus_export.hpp"
#include "model/io/printer_profile.hpp"

namespace nibrig::model::design {

// A design the chosen printer cannot make; what() names the printer and every reason.
class PrintRefused : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Each reason `printer` cannot make `print`, in words; empty when it can. A mix refused on a
// printer that cannot mix names the print's substitutes the printer has (print.substitutes, filled
// by a face with a space), nearest first, with their distance from the design.
std::vector<std::string> print_refusals(const io::PrinterProfile& printer, const StylusPrint& print);

// Throws PrintRefused joining print_refusals, naming the printer, when there is any.
void check_printable(const io::PrinterProfile& printer, const StylusPrint& print);

// Why no design on the line from `a` to `b` (the line a search walks) can be printed by `printer`
// for its materials, "" when one can: an end all of whose materials it has, or, when it mixes,
// every material of both. Lets a search be refused before it runs, not at its export.
std::string unprintable_line(const io::PrinterProfile& printer, const DesignPoint& a, const DesignPoint& b);

// The narrowest tip `printer` makes: its nozzle (FDM), min_feature_pixels pixels (MSLA), its dot
// pitch (PolyJet).
double smallest_tip_m(const io::PrinterProfile& printer);

// True when `printer` lists `material` (a catalog or table name, any case, aliases such as
// "vero" for "VeroClear" as catalog_material_name reads them).
bool printer_has(const io::PrinterProfile& printer, const std::string& material);

}  // namespace nibrig::model::design
