//! Procedural macros of the `blossom` workspace: compile-time expansion of the closed-form
//! blossom formulae (3), (9), (14) into unrolled, degree-specialised functions.
