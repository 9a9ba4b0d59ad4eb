//! Landing-gear method (placeholder, filled below).
