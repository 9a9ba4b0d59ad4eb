//! Integration tests of flapwright-gltf (one binary, a module per topic).

mod read_back;
