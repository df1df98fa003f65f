//! IEEE 488.2's status of one client: the error queue (SCPI's `SYSTem:ERRor?`, at most
//! 32 entries, the last replaced by -350 on overflow), the standard event status register
//! and its enable, the service request enable, and the status byte made of them.

use std::collections::VecDeque;

use super::error::ScpiError;

/// Most errors queued.
pub const QUEUE_LENGTH: usize = 32;

/// The event status register's operation-complete bit.
pub const OPC_BIT: u8 = 1;

/// One client's registers.
#[derive(Clone, Debug, Default)]
pub struct Registers {
    errors: VecDeque<ScpiError>,
    /// Standard event status register.
    pub esr: u8,
    /// Its enable (`*ESE`).
    pub ese: u8,
    /// Service request enable (`*SRE`).
    pub sre: u8,
}

impl Registers {
    /// Queues `error` and sets its event bit.
    pub fn push(&mut self, error: ScpiError) {
        self.esr |= error.event_bit();
        if self.errors.len() >= QUEUE_LENGTH {
            if let Some(last) = self.errors.back_mut() {
                *last = ScpiError::queue_overflow();
            }
            return;
        }
        self.errors.push_back(error);
    }

    /// The oldest error, or `0,"No error"`.
    pub fn next_error(&mut self) -> String {
        self.errors
            .pop_front()
            .map_or_else(|| "0,\"No error\"".to_string(), |e| e.answer())
    }

    /// Errors waiting.
    pub fn error_count(&self) -> usize {
        self.errors.len()
    }

    /// `*CLS`: the queue and the event register cleared.
    pub fn clear(&mut self) {
        self.errors.clear();
        self.esr = 0;
    }

    /// `*ESR?`: the event register, cleared by reading.
    pub fn take_esr(&mut self) -> u8 {
        std::mem::take(&mut self.esr)
    }

    /// `*STB?`: bit 2 an error waiting, bit 5 an enabled event, bit 6 a request for
    /// service (any bit enabled by `*SRE`); bit 7 the operation summary (measuring).
    pub fn status_byte(&self, measuring: bool) -> u8 {
        let mut stb = 0;
        if !self.errors.is_empty() {
            stb |= 1 << 2;
        }
        if self.esr & self.ese != 0 {
            stb |= 1 << 5;
        }
        if measuring {
            stb |= 1 << 7;
        }
        if stb & self.sre & !(1 << 6) != 0 {
            stb |= 1 << 6;
        }
        stb
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_queue_keeps_32_and_says_so_on_overflow_in_order() {
        let mut r = Registers::default();
        for k in 0..40 {
            r.push(ScpiError::out_of_range(&format!("value {k}")));
        }
        assert_eq!(r.error_count(), QUEUE_LENGTH);
        assert_eq!(r.next_error(), "-222,\"Data out of range;value 0\"");
        for _ in 1..31 {
            r.next_error();
        }
        assert_eq!(r.next_error(), "-350,\"Queue overflow\"");
        assert_eq!(r.next_error(), "0,\"No error\"");
        assert_eq!(r.take_esr(), 1 << 4, "execution error bit");
        assert_eq!(r.take_esr(), 0, "cleared by reading");
    }

    #[test]
    fn the_status_byte_summarises_errors_events_and_requests() {
        let mut r = Registers::default();
        assert_eq!(r.status_byte(false), 0);
        r.push(ScpiError::undefined_header("FOO"));
        assert_eq!(r.status_byte(false), 1 << 2);
        r.ese = 1 << 5;
        assert_eq!(r.status_byte(false), (1 << 2) | (1 << 5));
        r.sre = 1 << 5;
        assert_eq!(
            r.status_byte(true),
            (1 << 2) | (1 << 5) | (1 << 6) | (1 << 7)
        );
        r.clear();
        assert_eq!(r.status_byte(false), 0);
    }
}
