//! The `qmckit` command's tests, one binary (one link) with a module per concern: its
//! contract (formats, exit codes, one-line errors), each command against the library it
//! calls, the figures and the render studies, the report, and hostile input (every case
//! under a 4 GiB address space and a wall-clock bound).

mod common;

mod blue_noise;
mod catalog_cli;
mod cli;
mod cli_analysis;
mod cli_hostile;
mod cli_reference;
mod hostile;
mod integration_test;
mod lattice;
mod mask;
mod pcf;
mod pixel;
mod plot;
mod points_sets;
mod report;
mod scene;
mod spectrum;
mod variance;
