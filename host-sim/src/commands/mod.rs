//! One module per subcommand.

pub mod bench;
pub mod decode;
pub mod render;
pub mod view;
pub mod volume;
