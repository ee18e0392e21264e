//! `microtrace bench --numbers`: not written yet.

pub fn run(_args: &super::BenchArgs) -> anyhow::Result<()> {
    anyhow::bail!("bench --numbers is not implemented yet")
}
