//! Landing-gear method (doc 004) tests: filled with the module.
