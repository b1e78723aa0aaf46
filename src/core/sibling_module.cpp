#include "sibling_module.h"

#include <dlfcn.h>

#include <stdexcept>
#include <string>

namespace raylab {

void* sibling_module_symbol(const void* anchor, const char* file, const char* symbol, ModuleScope scope) {
  std::string path = file;  // the loader's own search, should the library's file not be known
  Dl_info info{};
  if (dladdr(anchor, &info) != 0 && info.dli_fname != nullptr) {
    const std::string library = info.dli_fname;
    const std::size_t slash = library.rfind('/');
    if (slash != std::string::npos) path = library.substr(0, slash + 1) + file;
  }
  void* module = dlopen(path.c_str(), RTLD_NOW | (scope == ModuleScope::kGlobal ? RTLD_GLOBAL : RTLD_LOCAL));
  if (module == nullptr) {
    const char* why = dlerror();
    throw std::runtime_error(std::string("cannot load raylab's module ") + file + ": " + (why ? why : path.c_str()));
  }
  void* address = dlsym(module, symbol);
  if (address == nullptr) throw std::runtime_error(path + " has no " + symbol);
  return address;
}

}  // namespace raylab
