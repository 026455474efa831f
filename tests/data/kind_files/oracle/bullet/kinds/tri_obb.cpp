// tri_obb's unit of a peer in the small tree of cli.kind_files tests: it makes oracle/bullet a peer
// with units, so the checklist asks every other kind for one there too.
