// 3MF through lib3mf 1.x's C interface (Debian 12 packages 1.8.1, the
// interface OpenSCAD 2021.01 was built against), opened on the first import
// rather than at every start (capsim/system/shared_library.h).
//
// OpenSCAD reads every mesh object resource of the model and ignores the
// build: an object no build item names is imported too, a build item's
// transform is not applied, components objects are left out, and the model's
// unit is not looked at. capsim reads the same triangles, so an import()
// renders what OpenSCAD renders from the same file.

#include "scene/meshes/threemf_import.h"

#include "capsim/system/sanitizers.h"
#include "capsim/system/shared_library.h"

#include <Model/COM/NMR_DLLInterfaces.h>
#include <fmt/format.h>

#include <memory>
#include <stdexcept>

namespace capsim::scene_file {

namespace {

// The functions of lib3mf's interface that the import calls, found in the
// library on first use. CAPSIM_LIB3MF_SONAME is the soname of the lib3MF the
// build found (CMakeLists.txt), so the interface the header declares is the
// one loaded.
struct Lib3mf {
#define CAPSIM_LIB3MF(name) decltype(&NMR::name) name = library().function<decltype(&NMR::name)>(#name)
  CAPSIM_LIB3MF(lib3mf_createmodel);
  CAPSIM_LIB3MF(lib3mf_release);
  CAPSIM_LIB3MF(lib3mf_getlasterror);
  CAPSIM_LIB3MF(lib3mf_model_queryreader);
  CAPSIM_LIB3MF(lib3mf_reader_readfrombuffer);
  CAPSIM_LIB3MF(lib3mf_model_getmeshobjects);
  CAPSIM_LIB3MF(lib3mf_resourceiterator_movenext);
  CAPSIM_LIB3MF(lib3mf_resourceiterator_getcurrent);
  CAPSIM_LIB3MF(lib3mf_resource_getresourceid);
  CAPSIM_LIB3MF(lib3mf_meshobject_getvertexcount);
  CAPSIM_LIB3MF(lib3mf_meshobject_gettrianglecount);
  CAPSIM_LIB3MF(lib3mf_meshobject_getvertices);
  CAPSIM_LIB3MF(lib3mf_meshobject_gettriangleindices);
#undef CAPSIM_LIB3MF

  static const SharedLibrary& library() {
    static const SharedLibrary lib(CAPSIM_LIB3MF_SONAME, "3MF import");
    return lib;
  }
};

// The table, filled on the first import; a library that cannot be loaded is
// refused at each import that needs it, naming the file.
const Lib3mf& lib3mf(const std::string& path) {
  try {
    static const Lib3mf table;
    return table;
  } catch (const std::runtime_error& e) {
    throw MeshFileError(fmt::format("{}: {}", path, e.what()));
  }
}

// lib3mf's handles are reference counted; each one the interface hands out
// (the model, the reader, the iterator and every resource it yields) is
// released once.
struct Release {
  const Lib3mf* lib;
  void operator()(NMR::PLib3MFBase* handle) const { lib->lib3mf_release(handle); }
};
using Handle = std::unique_ptr<NMR::PLib3MFBase, Release>;

class ThreeMfReader {
 public:
  ThreeMfReader(const std::string& path, const Lib3mf& lib) : path_(path), lib_(lib) {}

  [[noreturn]] void fail(const std::string& message) const {
    throw MeshFileError(fmt::format("{}: {}", path_, message));
  }

  // A failed call of `handle`'s interface, with lib3mf's own reason.
  void check(LIB3MFRESULT result, NMR::PLib3MFBase* handle, std::string_view doing) const {
    if (result == LIB3MF_OK) return;
    DWORD code = 0;
    LPCSTR why = nullptr;
    if (handle && lib_.lib3mf_getlasterror(handle, &code, &why) == LIB3MF_OK && why && *why)
      fail(fmt::format("{}: {} (lib3mf error {:#x})", doing, why, code));
    fail(fmt::format("{} (lib3mf error {:#x})", doing, static_cast<unsigned>(result)));
  }

  // One mesh object's vertices and triangles (no faces when it has none).
  MeshObject object(NMR::PLib3MFModelMeshObject* mesh) const {
    DWORD id = 0, nv = 0, nt = 0;
    check(lib_.lib3mf_resource_getresourceid(mesh, &id), mesh, "cannot read a mesh object's id");
    MeshObject o{fmt::format("{}: object {}", path_, id), {}};
    check(lib_.lib3mf_meshobject_getvertexcount(mesh, &nv), mesh, "cannot read a mesh object");
    check(lib_.lib3mf_meshobject_gettrianglecount(mesh, &nt), mesh, "cannot read a mesh object");
    if (nt == 0) return o;
    std::vector<NMR::MODELMESHVERTEX> vertices(nv);
    std::vector<NMR::MODELMESHTRIANGLE> triangles(nt);
    if (nv > 0)
      check(lib_.lib3mf_meshobject_getvertices(mesh, vertices.data(), nv, nullptr), mesh, "cannot read vertices");
    check(lib_.lib3mf_meshobject_gettriangleindices(mesh, triangles.data(), nt, nullptr), mesh,
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
  const Lib3mf& lib_;
};

Handle made(const Lib3mf& lib, LIB3MFRESULT result, NMR::PLib3MFBase* handle) {
  return Handle(result == LIB3MF_OK ? handle : nullptr, Release{&lib});
}

}  // namespace

std::vector<MeshObject> read_3mf(const std::string& path, std::string data) {
  const Lib3mf& lib = lib3mf(path);
  const ThreeMfReader r(path, lib);
  NMR::PLib3MFModel* model_handle = nullptr;
  const LIB3MFRESULT created = lib.lib3mf_createmodel(&model_handle);
  const Handle model = made(lib, created, model_handle);
  r.check(created, nullptr, "lib3mf cannot make a model");

  NMR::PLib3MFModelReader* reader_handle = nullptr;
  const LIB3MFRESULT queried = lib.lib3mf_model_queryreader(model.get(), "3mf", &reader_handle);
  const Handle reader = made(lib, queried, reader_handle);
  r.check(queried, model.get(), "lib3mf has no 3MF reader");
  r.check(lib.lib3mf_reader_readfrombuffer(reader.get(), reinterpret_cast<BYTE*>(data.data()), data.size()),
          reader.get(), "lib3mf cannot read it as a 3MF package");

  NMR::PLib3MFModelResourceIterator* it_handle = nullptr;
  const LIB3MFRESULT listed = lib.lib3mf_model_getmeshobjects(model.get(), &it_handle);
  const Handle objects = made(lib, listed, it_handle);
  r.check(listed, model.get(), "cannot list the mesh objects");
  std::vector<MeshObject> out;
  for (;;) {
    BOOL more = false;
    r.check(lib.lib3mf_resourceiterator_movenext(objects.get(), &more), objects.get(), "cannot list the mesh objects");
    if (!more) break;
    NMR::PLib3MFModelResource* object_handle = nullptr;
    const LIB3MFRESULT got = lib.lib3mf_resourceiterator_getcurrent(objects.get(), &object_handle);
    const Handle object = made(lib, got, object_handle);
    r.check(got, objects.get(), "cannot read a mesh object");
    // An object without triangles adds nothing to OpenSCAD's union.
    if (MeshObject o = r.object(object.get()); !o.mesh.faces.empty()) out.push_back(std::move(o));
  }
  if (out.empty()) r.fail("the model has no mesh object with a triangle");
  return out;
}

}  // namespace capsim::scene_file

#ifdef CAPSIM_ADDRESS_SANITIZER
// lib3mf 1.8.1 leaves a few hundred bytes of libzip's allocations behind on
// every package it reads (a bare create-read-release of a model leaks them
// too), which LeakSanitizer would report at the exit of any program that
// imports a 3MF file. capsim calls libzip through lib3mf alone, so leaks
// allocated inside libzip are lib3mf's and are not reported.
extern "C" const char* __lsan_default_suppressions() { return "leak:libzip.so\n"; }
#endif
