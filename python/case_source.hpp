#pragma once
// The case a Python call names, as magfem.Case keeps it: a file (`path`, relative paths in it
// resolved against its folder) or, when path is empty, YAML `text` named `name` in messages
// (Case.from_dict), with parameter overrides. Read and validated by the command line's reader.
#include <map>
#include <string>

#include "casefile/case_spec.hpp"

namespace magfem::python {

inline CaseSpec read_python_case(const std::string& path, const std::string& text,
                                 const std::string& name,
                                 const std::map<std::string, double>& parameters) {
  return path.empty() ? read_case_text(text, name, parameters) : read_case(path, parameters);
}

} // namespace magfem::python
