#include "model/mesh_io/stylus_3mf.hpp"

#include <Model/COM/NMR_DLLInterfaces.h>

#include <clocale>
#include <memory>
#include <stdexcept>
#include <string>

#include "model/io/atomic_file.hpp"

namespace nibrig::model::mesh_io {
namespace {

using namespace NMR;

// lib3mf sets the process's locale to "C" (LC_ALL) around its numbers and does not put it back: a
// Python session that exported a stylus then read and wrote its own files as ASCII. A call into it
// keeps the locale in force before and restores it when it ends.
class KeptLocale {
 public:
  KeptLocale() {
    if (const char* now = std::setlocale(LC_ALL, nullptr)) saved_ = now;
  }
  ~KeptLocale() {
    if (!saved_.empty()) std::setlocale(LC_ALL, saved_.c_str());
  }
  KeptLocale(const KeptLocale&) = delete;
  KeptLocale& operator=(const KeptLocale&) = delete;

 private:
  std::string saved_;
};

// Every lib3mf instance is released when its owner goes.
struct Release {
  void operator()(PLib3MFBase* p) const noexcept {
    if (p != nullptr) lib3mf_release(p);
  }
};
using Owned = std::unique_ptr<PLib3MFBase, Release>;

class Lib3mfCall {
 public:
  explicit Lib3mfCall(std::string where) : where_(std::move(where)) {}
  // Throws naming `what` and lib3mf's own message when `result` is a failure.
  void operator()(LIB3MFRESULT result, PLib3MFBase* instance, const std::string& what) const {
    if (result == LIB3MF_OK) return;
    std::string message = "error " + std::to_string(result);
    if (instance != nullptr) {
      DWORD code = 0;
      LPCSTR text = nullptr;
      if (lib3mf_getlasterror(instance, &code, &text) == LIB3MF_OK && text != nullptr &&
          *text != '\0')
        message = text;
    }
    throw std::runtime_error(where_ + ": lib3mf could not " + what + " (" + message + ")");
  }

 private:
  std::string where_;
};

MODELTRANSFORM translation_mm(const std::array<double, 3>& offset_m) {
  MODELTRANSFORM t{};
  for (int i = 0; i < 3; ++i) {
    t.m_fFields[i][i] = 1.0f;
    t.m_fFields[i][3] = static_cast<float>(1e3 * offset_m[static_cast<std::size_t>(i)]);
  }
  return t;
}

}  // namespace

void write_3mf(const std::filesystem::path& file, const ThreeMfPart& part) {
  if (part.regions.empty())
    throw std::invalid_argument(file.string() + ": a 3MF part needs at least one region");
  io::output_target(file);  // refused before the model is built: a folder, a device, an input
  const KeptLocale locale;
  const Lib3mfCall call(file.string());
  PLib3MFModel* raw = nullptr;
  call(lib3mf_createmodel(&raw), nullptr, "create a model");
  const Owned model(raw);
  call(lib3mf_model_setunit(model.get(), MODELUNIT_MILLIMETER), model.get(), "set millimetres");
  for (const auto& [key, value] : part.metadata)
    call(lib3mf_model_addmetadatautf8(model.get(), key.c_str(), value.c_str()), model.get(),
         "add metadata " + key);

  PLib3MFModelBaseMaterial* materials_raw = nullptr;
  call(lib3mf_model_addbasematerialgroup(model.get(), &materials_raw), model.get(),
       "add the materials");
  const Owned materials(materials_raw);
  DWORD materials_id = 0;
  call(lib3mf_basematerial_getresourceid(materials.get(), &materials_id), materials.get(),
       "number the materials");

  // A 3MF resource must come before what refers to it: the regions' objects, then the part.
  std::vector<Owned> meshes;
  for (const auto& region : part.regions) {
    const auto& s = region.surface;
    if (s.triangles.empty())
      throw std::invalid_argument(file.string() + ": region '" + s.name + "' has no triangles");
    DWORD material_index = 0;
    call(lib3mf_basematerial_addmaterialutf8(materials.get(), region.material.c_str(),
                                             region.display_rgb[0], region.display_rgb[1],
                                             region.display_rgb[2], &material_index),
         materials.get(), "add material " + region.material);
    PLib3MFModelMeshObject* mesh_raw = nullptr;
    call(lib3mf_model_addmeshobject(model.get(), &mesh_raw), model.get(), "add region " + s.name);
    Owned mesh(mesh_raw);
    call(lib3mf_object_setnameutf8(mesh.get(), s.name.c_str()), mesh.get(),
         "name region " + s.name);
    std::vector<MODELMESHVERTEX> vertices(s.vertices.size());
    for (std::size_t i = 0; i < s.vertices.size(); ++i)
      for (int k = 0; k < 3; ++k)
        vertices[i].m_fPosition[k] =
            static_cast<float>(1e3 * s.vertices[i][static_cast<std::size_t>(k)]);
    std::vector<MODELMESHTRIANGLE> triangles(s.triangles.size());
    for (std::size_t i = 0; i < s.triangles.size(); ++i)
      for (int k = 0; k < 3; ++k)
        triangles[i].m_nIndices[k] = s.triangles[i][static_cast<std::size_t>(k)];
    call(lib3mf_meshobject_setgeometry(mesh.get(), vertices.data(),
                                       static_cast<DWORD>(vertices.size()), triangles.data(),
                                       static_cast<DWORD>(triangles.size())),
         mesh.get(), "set region " + s.name + "'s triangles");
    PLib3MFDefaultPropertyHandler* property_raw = nullptr;
    call(lib3mf_object_createdefaultpropertyhandler(mesh.get(), &property_raw), mesh.get(),
         "give region " + s.name + " a material");
    const Owned property(property_raw);
    call(
        lib3mf_defaultpropertyhandler_setbasematerial(property.get(), materials_id, material_index),
        property.get(), "give region " + s.name + " its material");
    meshes.push_back(std::move(mesh));
  }
  PLib3MFModelComponentsObject* assembly_raw = nullptr;
  call(lib3mf_model_addcomponentsobject(model.get(), &assembly_raw), model.get(), "add the part");
  const Owned assembly(assembly_raw);
  call(lib3mf_object_setnameutf8(assembly.get(), part.name.c_str()), assembly.get(),
       "name the part");
  for (const auto& mesh : meshes) {
    PLib3MFModelComponent* component_raw = nullptr;
    call(lib3mf_componentsobject_addcomponent(assembly.get(), mesh.get(), nullptr, &component_raw),
         assembly.get(), "put a region in the part");
    const Owned component(component_raw);
  }
  MODELTRANSFORM placement = translation_mm(part.placement_m);
  PLib3MFModelBuildItem* item_raw = nullptr;
  call(lib3mf_model_addbuilditem(model.get(), assembly.get(), &placement, &item_raw), model.get(),
       "place the part");
  const Owned item(item_raw);

  for (const auto& [path, content] : part.attachments) {
    // The relationship type is ours: PrusaSlicer finds its config by the path alone.
    std::string uri = "/" + path, relationship = "http://schemas.nibrig.org/3mf/slicer-config";
    PLib3MFModelAttachment* attachment_raw = nullptr;
    call(lib3mf_model_addattachmentutf8(model.get(), uri.data(), relationship.data(),
                                        &attachment_raw),
         model.get(), "attach " + path);
    const Owned attachment(attachment_raw);
    std::string bytes = content;
    call(lib3mf_attachment_readfrombuffer(attachment.get(), reinterpret_cast<BYTE*>(bytes.data()),
                                          bytes.size()),
         attachment.get(), "fill " + path);
  }

  PLib3MFModelWriter* writer_raw = nullptr;
  call(lib3mf_model_querywriter(model.get(), "3mf", &writer_raw), model.get(), "make a 3MF writer");
  const Owned writer(writer_raw);
  // Made in memory and written by write_file_atomically: lib3mf's own file writer aborts the
  // process when the disk is full (its exception escapes a destructor).
  ULONG64 size = 0;
  call(lib3mf_writer_getstreamsize(writer.get(), &size), writer.get(), "measure the file");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  call(lib3mf_writer_writetobuffer(writer.get(), reinterpret_cast<BYTE*>(bytes.data()), size),
       writer.get(), "write the file");
  io::write_file_atomically(file, bytes);
}

std::vector<ThreeMfRegion> read_3mf_regions(const std::filesystem::path& file) {
  const KeptLocale locale;
  const Lib3mfCall call(file.string());
  PLib3MFModel* raw = nullptr;
  call(lib3mf_createmodel(&raw), nullptr, "create a model");
  const Owned model(raw);
  PLib3MFModelReader* reader_raw = nullptr;
  call(lib3mf_model_queryreader(model.get(), "3mf", &reader_raw), model.get(), "make a 3MF reader");
  const Owned reader(reader_raw);
  call(lib3mf_reader_readfromfileutf8(reader.get(), file.c_str()), reader.get(), "read the file");
  DWORD unit = MODELUNIT_MILLIMETER;
  call(lib3mf_model_getunit(model.get(), &unit), model.get(), "read the unit");
  const double metres_per_unit = unit == MODELUNIT_MICROMETER   ? 1e-6
                                 : unit == MODELUNIT_CENTIMETER ? 1e-2
                                 : unit == MODELUNIT_INCH       ? 0.0254
                                 : unit == MODELUNIT_FOOT       ? 0.3048
                                 : unit == MODELUNIT_METER      ? 1.0
                                                                : 1e-3;
  PLib3MFModelResourceIterator* it_raw = nullptr;
  call(lib3mf_model_getmeshobjects(model.get(), &it_raw), model.get(), "list the regions");
  const Owned it(it_raw);
  std::vector<ThreeMfRegion> out;
  BOOL more = false;
  while (lib3mf_resourceiterator_movenext(it.get(), &more) == LIB3MF_OK && more) {
    PLib3MFModelResource* mesh_raw = nullptr;
    call(lib3mf_resourceiterator_getcurrent(it.get(), &mesh_raw), it.get(), "read a region");
    const Owned mesh(mesh_raw);
    ThreeMfRegion region;
    char name[256] = {};
    ULONG name_length = 0;
    call(lib3mf_object_getnameutf8(mesh.get(), name, sizeof name, &name_length), mesh.get(),
         "read a region's name");
    region.surface.name = name;
    DWORD vertex_count = 0, triangle_count = 0;
    call(lib3mf_meshobject_getvertexcount(mesh.get(), &vertex_count), mesh.get(), "count vertices");
    call(lib3mf_meshobject_gettrianglecount(mesh.get(), &triangle_count), mesh.get(),
         "count triangles");
    std::vector<MODELMESHVERTEX> vertices(vertex_count);
    std::vector<MODELMESHTRIANGLE> triangles(triangle_count);
    call(lib3mf_meshobject_getvertices(mesh.get(), vertices.data(), vertex_count, nullptr),
         mesh.get(), "read vertices");
    call(
        lib3mf_meshobject_gettriangleindices(mesh.get(), triangles.data(), triangle_count, nullptr),
        mesh.get(), "read triangles");
    for (const auto& v : vertices)
      region.surface.vertices.push_back({metres_per_unit * v.m_fPosition[0],
                                         metres_per_unit * v.m_fPosition[1],
                                         metres_per_unit * v.m_fPosition[2]});
    for (const auto& t : triangles)
      region.surface.triangles.push_back({t.m_nIndices[0], t.m_nIndices[1], t.m_nIndices[2]});
    PLib3MFDefaultPropertyHandler* property_raw = nullptr;
    if (lib3mf_object_createdefaultpropertyhandler(mesh.get(), &property_raw) == LIB3MF_OK) {
      const Owned property(property_raw);
      DWORD group = 0, index = 0;
      if (lib3mf_defaultpropertyhandler_getbasematerial(property.get(), &group, &index) ==
          LIB3MF_OK) {
        PLib3MFModelBaseMaterial* materials_raw = nullptr;
        if (lib3mf_model_getbasematerialbyid(model.get(), group, &materials_raw) == LIB3MF_OK) {
          const Owned materials(materials_raw);
          char material[256] = {};
          ULONG material_length = 0;
          if (lib3mf_basematerial_getnameutf8(materials.get(), index, material, sizeof material,
                                              &material_length) == LIB3MF_OK)
            region.material = material;
        }
      }
    }
    out.push_back(std::move(region));
  }
  return out;
}

}  // namespace nibrig::model::mesh_io
