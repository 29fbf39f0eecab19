#include "compiler/lower/feeds.h"

#include "compiler/lower/lower_body.h"

namespace arbc::lower {

namespace {

const ast::DerivedEventDecl* find_derived(const ast::Spec& spec, const std::string& name) {
  for (const ast::DerivedEventDecl& d : spec.derived_events)
    if (d.name == name) return &d;
  return nullptr;
}

}  // namespace

std::vector<FeedGroup> plan_feeds(const ast::Spec& spec, const std::set<std::string>& read) {
  std::vector<FeedGroup> groups;
  auto group_for = [&](const ast::EventSymbol& sym) -> FeedGroup& {
    for (FeedGroup& g : groups)
      if (g.source == sym.source) return g;
    FeedGroup g;
    g.source = sym.source;
    g.loc = sym.loc;
    g.plan.kind = MonitorPlan::Kind::Feed;
    g.plan.message_name = sym.source.substr(sym.source.find('.') + 1);
    groups.push_back(std::move(g));
    return groups.back();
  };
  for (const ast::EventSymbol& sym : spec.event_symbols) {
    if (sym.kind == ast::EventSymbol::Kind::Manual || !read.count(sym.name)) continue;
    if (sym.kind == ast::EventSymbol::Kind::Status) {
      FeedGroup& g = group_for(sym);
      g.plan.status_flags.push_back(
          {sym.name, sym.flag.empty() ? sym.name : sym.flag, sym.lifetime, sym.loc});
      g.sets.push_back(sym.name);
      g.unsets.push_back(sym.name);
    } else {
      const ast::DerivedEventDecl* decl = find_derived(spec, sym.name);
      if (!decl) continue;  // sema guarantees one; nothing to generate otherwise
      FeedGroup& g = group_for(sym);
      std::optional<Nanos> life;
      if (decl->lifetime) life = decl->lifetime->nanos;
      const ast::PortDecl* source = decl->source.port_decl;
      g.plan.derived.push_back(
          {sym.name, lower_expr(*decl->predicate, source ? source->type.resolved : nullptr), life,
           sym.loc});
      g.sets.push_back(sym.name);
      if (!life) g.unsets.push_back(sym.name);
    }
  }
  return groups;
}

}  // namespace arbc::lower
