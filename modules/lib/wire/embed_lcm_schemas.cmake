# Writes a C++ file holding the text of every lcmtypes/*.lcm file, so the
# readable decoder and the message guard know every message type without a printer per type.
# Usage: cmake -DSCHEMA_DIR=<lcmtypes> -DOUTPUT=<file.cpp> -P embed_lcm_schemas.cmake
file(GLOB schema_files ${SCHEMA_DIR}/*.lcm)
list(SORT schema_files)
set(entries "")
foreach(schema_file ${schema_files})
  get_filename_component(name ${schema_file} NAME)
  file(READ ${schema_file} text)
  string(APPEND entries "      {\"${name}\", R\"lcm_schema(${text})lcm_schema\"},\n")
endforeach()
set(content "// Generated from lcmtypes/*.lcm by embed_lcm_schemas.cmake: do not edit.
#include \"lib/wire/embedded_schemas.hpp\"

namespace beft::wire {

const std::vector<EmbeddedSchema>& embeddedLcmSchemas() {
  static const std::vector<EmbeddedSchema> schemas = {
${entries}  };
  return schemas;
}

}  // namespace beft::wire
")
file(WRITE ${OUTPUT} "${content}")
