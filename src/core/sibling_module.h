#pragma once
/// \file
/// Internal to raylab's libraries: loading a module that lies in the same folder as the library
/// asking for it (build tree, install and wheel alike). Parts that need a heavy dependency only
/// sometimes (MPI for MPI runs, OpenEXR for EXR files) live in such modules, so that a process
/// that never uses them does not load that dependency's libraries.

#include <stdexcept>
#include <string>

namespace raylab {

/// Whether the module's symbols join the global scope: needed when the module's own
/// dependencies load plugins that look symbols up there (Open MPI's components).
enum class ModuleScope { kLocal, kGlobal };

/// The address of `symbol` in module `file` (a file name, no folder), loaded (once; never
/// unloaded) from the folder of the library that holds `anchor`, the address of a function of
/// that library. Throws std::runtime_error naming the module and the loader's reason when the
/// module cannot be loaded or lacks the symbol.
void* sibling_module_symbol(const void* anchor, const char* file, const char* symbol, ModuleScope scope);

/// What the module's entry point `symbol` (a function taking nothing and returning `const T*`)
/// returns, the module loaded (kLocal) and the entry called at the first call only, from any
/// thread; each call throws std::runtime_error, with the first one's reason, when it failed.
template <class T>
const T& sibling_module_entry(const void* anchor, const char* file, const char* symbol) {
  struct Loaded {
    const T* value = nullptr;
    std::string error;
  };
  static const Loaded loaded = [&] {
    Loaded l;
    try {
      l.value = reinterpret_cast<const T* (*)()>(sibling_module_symbol(anchor, file, symbol, ModuleScope::kLocal))();
    } catch (const std::exception& e) {
      l.error = e.what();
    }
    return l;
  }();
  if (loaded.value == nullptr) throw std::runtime_error(loaded.error);
  return *loaded.value;
}

}  // namespace raylab
