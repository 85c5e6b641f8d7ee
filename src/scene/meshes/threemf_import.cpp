// 3MF through lib3mf 1.x's C interface (Debian 12 packages 1.8.1, the
// interface OpenSCAD 2021.01 was built against).
//
// OpenSCAD reads every mesh object resource of the model and ignores the
// build: an object no build item names is imported too, a build item's
// transform is not applied, components objects are left out, and the model's
// unit is not looked at. capsim reads the same triangles, so an import()
// renders what OpenSCAD renders from the same file.

#include "scene/meshes/threemf_import.h"

#include <Model/COM/NMR_DLLInterfaces.h>
#include <fmt/format.h>

#include <memory>

namespace capsim::scene_file {

namespace {

// lib3mf's handles are reference counted; each one the interface hands out
// (the model, the reader, the iterator and every resource it yields) is
// released once.
struct Release {
  void operator()(NMR::PLib3MFBase* handle) const { NMR::lib3mf_release(handle); }
};
using Handle = std::unique_ptr<NMR::PLib3MFBase, Release>;

class ThreeMfReader {
 public:
  explicit ThreeMfReader(const std::string& path) : path_(path) {}

  [[noreturn]] void fail(const std::string& message) const {
    throw MeshFileError(fmt::format("{}: {}", path_, message));
  }

  // A failed call of `handle`'s interface, with lib3mf's own reason.
  void check(LIB3MFRESULT result, NMR::PLib3MFBase* handle, std::string_view doing) const {
    if (result == LIB3MF_OK) return;
    DWORD code = 0;
    LPCSTR why = nullptr;
    if (handle && NMR::lib3mf_getlasterror(handle, &code, &why) == LIB3MF_OK && why && *why)
      fail(fmt::format("{}: {} (lib3mf error {:#x})", doing, why, code));
    fail(fmt::format("{} (lib3mf error {:#x})", doing, static_cast<unsigned>(result)));
  }

  // One mesh object's vertices and triangles (no faces when it has none).
  MeshObject object(NMR::PLib3MFModelMeshObject* mesh) const {
    DWORD id = 0, nv = 0, nt = 0;
    check(NMR::lib3mf_resource_getresourceid(mesh, &id), mesh, "cannot read a mesh object's id");
    MeshObject o{fmt::format("{}: object {}", path_, id), {}};
    check(NMR::lib3mf_meshobject_getvertexcount(mesh, &nv), mesh, "cannot read a mesh object");
    check(NMR::lib3mf_meshobject_gettrianglecount(mesh, &nt), mesh, "cannot read a mesh object");
    if (nt == 0) return o;
    std::vector<NMR::MODELMESHVERTEX> vertices(nv);
    std::vector<NMR::MODELMESHTRIANGLE> triangles(nt);
    if (nv > 0)
      check(NMR::lib3mf_meshobject_getvertices(mesh, vertices.data(), nv, nullptr), mesh, "cannot read vertices");
    check(NMR::lib3mf_meshobject_gettriangleindices(mesh, triangles.data(), nt, nullptr), mesh,
          "cannot read triangles");
    o.mesh.points.reserve(nv);
    for (DWORD i = 0; i < nv; ++i) {
      const glm::dvec3 p(vertices[i].m_fPosition[0], vertices[i].m_fPosition[1], vertices[i].m_fPosition[2]);
      for (int k = 0; k < 3; ++k)
        if (const std::string fault = coordinate_fault(p[k]); !fault.empty())
          fail(fmt::format("object {}: vertex {}: coordinate {} {}", id, i, p[k], fault));
      o.mesh.points.push_back(p);
    }
    o.mesh.faces.reserve(nt);
    for (DWORD t = 0; t < nt; ++t) {
      std::vector<std::uint32_t> face(triangles[t].m_nIndices, triangles[t].m_nIndices + 3);
      for (std::uint32_t i : face)
        if (i >= nv) fail(fmt::format("object {}: triangle {} names vertex {}, but the object has {}", id, t, i, nv));
      o.mesh.faces.push_back(std::move(face));
    }
    return o;
  }

 private:
  const std::string& path_;
};

Handle made(LIB3MFRESULT result, NMR::PLib3MFBase* handle) { return Handle(result == LIB3MF_OK ? handle : nullptr); }

}  // namespace

std::vector<MeshObject> read_3mf(const std::string& path, std::string data) {
  const ThreeMfReader r(path);
  NMR::PLib3MFModel* model_handle = nullptr;
  const LIB3MFRESULT created = NMR::lib3mf_createmodel(&model_handle);
  const Handle model = made(created, model_handle);
  r.check(created, nullptr, "lib3mf cannot make a model");

  NMR::PLib3MFModelReader* reader_handle = nullptr;
  const LIB3MFRESULT queried = NMR::lib3mf_model_queryreader(model.get(), "3mf", &reader_handle);
  const Handle reader = made(queried, reader_handle);
  r.check(queried, model.get(), "lib3mf has no 3MF reader");
  r.check(NMR::lib3mf_reader_readfrombuffer(reader.get(), reinterpret_cast<BYTE*>(data.data()), data.size()),
          reader.get(), "lib3mf cannot read it as a 3MF package");

  NMR::PLib3MFModelResourceIterator* it_handle = nullptr;
  const LIB3MFRESULT listed = NMR::lib3mf_model_getmeshobjects(model.get(), &it_handle);
  const Handle objects = made(listed, it_handle);
  r.check(listed, model.get(), "cannot list the mesh objects");
  std::vector<MeshObject> out;
  for (;;) {
    BOOL more = false;
    r.check(NMR::lib3mf_resourceiterator_movenext(objects.get(), &more), objects.get(), "cannot list the mesh objects");
    if (!more) break;
    NMR::PLib3MFModelResource* object_handle = nullptr;
    const LIB3MFRESULT got = NMR::lib3mf_resourceiterator_getcurrent(objects.get(), &object_handle);
    const Handle object = made(got, object_handle);
    r.check(got, objects.get(), "cannot read a mesh object");
    // An object without triangles adds nothing to OpenSCAD's union.
    if (MeshObject o = r.object(object.get()); !o.mesh.faces.empty()) out.push_back(std::move(o));
  }
  if (out.empty()) r.fail("the model has no mesh object with a triangle");
  return out;
}

}  // namespace capsim::scene_file

#if defined(__SANITIZE_ADDRESS__)
#define CAPSIM_LEAK_CHECKED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CAPSIM_LEAK_CHECKED 1
#endif
#endif
#ifdef CAPSIM_LEAK_CHECKED
// lib3mf 1.8.1 leaves a few hundred bytes of libzip's allocations behind on
// every package it reads (a bare create-read-release of a model leaks them
// too), which LeakSanitizer would report at the exit of any program that
// imports a 3MF file. capsim calls libzip through lib3mf alone, so leaks
// allocated inside libzip are lib3mf's and are not reported.
extern "C" const char* __lsan_default_suppressions() { return "leak:libzip.so\n"; }
#endif
