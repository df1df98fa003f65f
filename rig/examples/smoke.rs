use rig::*;
fn main() {
    let args: Vec<f64> = std::env::args().skip(1).map(|a| a.parse().unwrap()).collect();
    let (rpm, load, secs) = (args[0], args[1], args[2]);
    let p = preset("basmaji-1983").unwrap();
    let mut plant = Plant::new(p, Schedule::constant(rpm, load), PlantConfig::default()).unwrap();
    println!("substeps {}", plant.substeps());
    let n = (secs * 51200.0) as usize;
    let mut block = SignalBlock::default();
    let t0 = std::time::Instant::now();
    let mut last_block = SignalBlock::default();
    for _ in 0..(n / 51200) { block.clear(); plant.run(51200, &mut block).unwrap(); }
    std::mem::swap(&mut block, &mut last_block);
    let n = 51200; let block = last_block;
    let wall = t0.elapsed().as_secs_f64();
    println!("sim {secs} s wall {wall:.3} s ratio {:.0}x switches {} impacts {}", secs / wall, plant.switch_count(), plant.impacts().len());
    let tq = &block.shaft_torque_nm[1];
    let last = &tq[n - 51200..];
    let mean = last.iter().sum::<f64>() / last.len() as f64;
    let rms = (last.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / last.len() as f64).sqrt();
    println!("slow steps {}", rig::plant::SLOW.load(std::sync::atomic::Ordering::Relaxed));
    println!("torque mean {mean:.4} ac rms {rms:.4}");
    let revs = plant.revolutions();
    let k = revs.len();
    let tail = &revs[k.saturating_sub(40)..];
    println!("regime {:?}", classify(tail, &RegimeCriteria::default()));
    for r in &revs[k.saturating_sub(6)..] { println!("{:.5} {:?}", r.time_s, &r.state[..3]); }
    for i in plant.impacts().iter().rev().take(5) { println!("{i:?}"); }
}
