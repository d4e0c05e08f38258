//! Integration tests of `boltzone::compare` and `boltzone::reference`: Tables 1 and 2, the
//! design map, the report's data, and the `table1`, `table2`, `map` commands.

#[path = "../common/mod.rs"]
mod common;

mod cli;
mod map;
mod map_fallback;
mod map_method;
mod map_table;
mod one_question;
mod reference;
mod table_units;
mod tables;
