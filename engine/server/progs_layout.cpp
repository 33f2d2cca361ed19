#include "server/progs_layout.h"

namespace nq::server {

Result<ProgsLayout> resolve_layout(const vm::Progs& progs) {
    ProgsLayout layout;
    std::string missing;
    auto find = [&](const vm::Def* def, const char* name, vm::DefType type, bool is_field,
                    uint32_t& out) {
        if (!missing.empty()) return;
        if (!def) {
            missing = std::string(is_field ? "field ." : "global ") + name + " is missing";
        } else if (def->def_type() != type) {
            missing = std::string(is_field ? "field ." : "global ") + name + " has type " +
                      std::to_string(int(def->def_type()));
        } else {
            out = def->offset;
        }
    };
#define NQ_FIND_GLOBAL(name, type) \
    find(progs.find_global(#name), #name, vm::DefType::type, false, layout.globals.name);
#define NQ_FIND_FIELD(name, type) \
    find(progs.find_field(#name), #name, vm::DefType::type, true, layout.fields.name);
    NQ_SYSTEM_GLOBALS(NQ_FIND_GLOBAL)
    NQ_SYSTEM_FIELDS(NQ_FIND_FIELD)
#undef NQ_FIND_GLOBAL
#undef NQ_FIND_FIELD
    if (!missing.empty()) {
        return Error{progs.name, 0, "not a Quake game progs: system " + missing};
    }
    auto optional = [&](const char* name, uint32_t& out) {
        const vm::Def* def = progs.find_field(name);
        if (def && def->def_type() == vm::DefType::float_) out = def->offset;
    };
    optional("alpha", layout.field_alpha);
    optional("gravity", layout.field_gravity);
    optional("items2", layout.field_items2);
    return layout;
}

}  // namespace nq::server
