// Catalogs of one lab put together: the bundled catalog (the paper's tools, the targets of a
// design) and the lab's own (its prints captured on the rig, whose friction a prediction of its
// material reads), so that one catalog answers both.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "model/io/catalog_file.hpp"

namespace nibrig::model::catalog {

struct NamedCatalog {
  std::string name;  // how errors and notes call it (its file)
  io::Catalog catalog;
};

// Every tool, surface and pairing of each catalog, in order, the notes kept with the name of the
// catalog they came from. A tool or surface in two catalogs must be the same entry; a tool
// measured on one surface in two catalogs is refused (which measurement to keep is the lab's
// choice). Throws std::invalid_argument naming both catalogs and what differs.
io::Catalog merge_catalogs(const std::vector<NamedCatalog>& catalogs);

}  // namespace nibrig::model::catalog
