//! I2C0, the Stellaris I2C master (LM3S811 data sheet, "Inter-Integrated Circuit (I2C)
//! Interface"), as an `embedded-hal` 1.0 [`I2c`] bus that writes: the OLED is only written. One
//! byte at a time through the master data register, each started by a write to the control
//! register: START with the first byte, STOP with the last, the bus's ERROR bit read after each
//! (no acknowledge: no device at the address). QEMU completes each byte at once; on the chip
//! the BUSY bit is polled first.

use embedded_hal::i2c::{self, ErrorKind, I2c, NoAcknowledgeSource, Operation};

use crate::board::stellaris::{sysctl, GpioPort, Register};

const BASE: usize = 0x4002_0000;
/// Master slave address: the 7-bit address above the receive bit (0: send).
const MSA: Register = Register::at(BASE);
/// Master control (written) and status (read).
const MCS: Register = Register::at(BASE + 0x04);
/// Master data: the byte the next RUN sends.
const MDR: Register = Register::at(BASE + 0x08);
/// Master timer period: SCL = system clock / (20 (1 + TPR)).
const MTPR: Register = Register::at(BASE + 0x0C);
/// Master configuration: MFE (bit 4) enables the master.
const MCR: Register = Register::at(BASE + 0x20);

const RUN: u32 = 1 << 0;
const START: u32 = 1 << 1;
const STOP: u32 = 1 << 2;
const BUSY: u32 = 1 << 0;
const ERROR: u32 = 1 << 1;
const MASTER_ENABLE: u32 = 1 << 4;

/// I2C0 as a master on PB2 (SCL) and PB3 (SDA).
pub struct I2c0 {
    _configured: (),
}

impl I2c0 {
    /// Clocks I2C0 and port B, gives PB2 and PB3 to the controller (open drain) and enables
    /// the master at 100 kHz from the 6 MHz clock the part starts on.
    pub fn new() -> Self {
        sysctl::RCGC1.set_bits(1 << 12);
        sysctl::RCGC2.set_bits(1 << 1);
        let pins = (1 << 2) | (1 << 3);
        GpioPort::B.alternate_function().set_bits(pins);
        GpioPort::B.open_drain().set_bits(pins);
        GpioPort::B.digital_enable().set_bits(pins);
        MCR.write(MASTER_ENABLE);
        MTPR.write(2);
        Self { _configured: () }
    }

    /// Sends one byte with `control` (RUN, and START and STOP as it falls), waiting while the
    /// controller is busy; false if it reports an error.
    fn send_byte(byte: u8, control: u32) -> bool {
        MDR.write(u32::from(byte));
        MCS.write(control);
        while MCS.read() & BUSY != 0 {}
        MCS.read() & ERROR == 0
    }
}

/// What went wrong on the bus.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Error {
    /// The controller's ERROR bit: no device acknowledged.
    NoAcknowledge,
    /// A read was asked for: this bus only writes.
    ReadUnsupported,
}

impl i2c::Error for Error {
    fn kind(&self) -> ErrorKind {
        match self {
            Error::NoAcknowledge => ErrorKind::NoAcknowledge(NoAcknowledgeSource::Unknown),
            Error::ReadUnsupported => ErrorKind::Other,
        }
    }
}

impl i2c::ErrorType for I2c0 {
    type Error = Error;
}

impl I2c for I2c0 {
    /// The operations' bytes in one transfer: START before the first, STOP after the last.
    fn transaction(&mut self, address: u8, operations: &mut [Operation<'_>]) -> Result<(), Error> {
        let mut total = 0usize;
        for operation in operations.iter() {
            match operation {
                Operation::Write(bytes) => total += bytes.len(),
                Operation::Read(_) => return Err(Error::ReadUnsupported),
            }
        }
        MSA.write(u32::from(address) << 1);
        let mut sent = 0usize;
        for operation in operations.iter() {
            let Operation::Write(bytes) = operation else { continue };
            for byte in bytes.iter() {
                let mut control = RUN;
                if sent == 0 {
                    control |= START;
                }
                sent += 1;
                if sent == total {
                    control |= STOP;
                }
                if !Self::send_byte(*byte, control) {
                    if sent != total {
                        MCS.write(STOP);
                    }
                    return Err(Error::NoAcknowledge);
                }
            }
        }
        Ok(())
    }
}
