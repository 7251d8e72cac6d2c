//! The `rtc` command line: `rtc check FILE`, `rtc render FILE`.
#![forbid(unsafe_code)]

fn main() {
    println!("rtc {}", env!("CARGO_PKG_VERSION"));
}
