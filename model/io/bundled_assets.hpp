// Where the bundled assets are (the default catalog, materials, stylus designs, threshold curve):
// $NIBRIG_ASSETS, else the installed share/nibrig/assets when the program is installed, else the
// repository's assets/ folder this binary was built from. Every face finds its defaults here.
#pragma once

#include <filesystem>

namespace nibrig::model::io {

std::filesystem::path assets_dir();

// <prefix>/share/nibrig for an installed program (cmake --install, the Debian packages): the first
// share/nibrig holding assets/ beside a folder above the file this code runs from (<prefix>/bin/
// nibrig, or the Python module under <prefix>/lib/python3/dist-packages); else empty (a build
// tree).
std::filesystem::path installed_share_dir();

// assets_dir() / relative, or a clear error naming what is missing and how to point at it.
std::filesystem::path asset(const std::filesystem::path& relative);

// The bundled files a default stands for, each found through asset().
std::filesystem::path default_catalog();         // default_catalog.json
std::filesystem::path default_materials();       // materials.json
std::filesystem::path default_stylus_design();   // the printed stylus with a 2 mm VeroClear tip
// The detection threshold the descriptors are weighted by unless told otherwise (Israr et al.
// 2006, pen hold).
std::filesystem::path default_threshold_curve();

// `path`, or the default when it is empty: how every option "(default: the bundled one)" reads.
std::filesystem::path or_default(const std::filesystem::path& path,
                                 std::filesystem::path (*fallback)());

}  // namespace nibrig::model::io
