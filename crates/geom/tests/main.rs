//! Integration tests of flapwright-geom (one binary, a module per topic).

mod collision;
mod dat;
mod fixture;
mod mass;
mod naca;
mod parts;
mod penetration;
mod scene;
mod two_element;
mod volume;
mod wing;
