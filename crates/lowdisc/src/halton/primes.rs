//! The prime bases of the Halton sequence, computed at compile time.
//!
//! [`PRIMES`] holds every prime below `2^16` (2, 3, 5, ..., 65521: the first
//! [`NUM_DIMENSIONS`] = 6,542 primes), produced by a `const fn` sieve of
//! Eratosthenes, so no table is committed. Dimension `d` of the Halton
//! sequence uses base `PRIMES[d]`; every base fits the `u16` entries of the
//! digit-permutation tables.
//!
//! For each base the module also fixes the number of digits the randomized
//! sequences scramble, [`scrambled_digits`]: the smallest `K` with
//! `b^K >= 2^64`, so the digits left out weigh less than `b^-K <= 2^-64`.

/// The number of Halton dimensions (one per prime base below `2^16`).
pub const NUM_DIMENSIONS: u32 = 6542;

/// Bases are below this bound.
const BASE_LIMIT: usize = 1 << 16;

/// The first [`NUM_DIMENSIONS`] primes, in increasing order.
pub static PRIMES: [u32; NUM_DIMENSIONS as usize] = first_primes();

/// The primes below [`BASE_LIMIT`], by a sieve of Eratosthenes (crossing out
/// the multiples of each prime from its square on).
const fn first_primes() -> [u32; NUM_DIMENSIONS as usize] {
    let mut composite = [false; BASE_LIMIT];
    let mut p = 2usize;
    while p * p < BASE_LIMIT {
        if !composite[p] {
            let mut m = p * p;
            while m < BASE_LIMIT {
                composite[m] = true;
                m += p;
            }
        }
        p += 1;
    }
    let mut primes = [0u32; NUM_DIMENSIONS as usize];
    let (mut count, mut candidate) = (0usize, 2usize);
    while candidate < BASE_LIMIT {
        if !composite[candidate] {
            // Indexing past the end (a wrong NUM_DIMENSIONS) fails the build.
            primes[count] = candidate as u32;
            count += 1;
        }
        candidate += 1;
    }
    // Too few primes for NUM_DIMENSIONS also fails the build.
    assert!(count == NUM_DIMENSIONS as usize);
    primes
}

/// The smallest `K` with `base^K >= 2^64`: how many digits the randomized
/// Halton variants scramble in base `base` (64 for base 2, 41 for base 3,
/// 5 for base 8161).
pub const fn scrambled_digits(base: u32) -> u32 {
    let mut power: u128 = 1;
    let mut digits = 0u32;
    while power < (1u128 << 64) {
        power *= base as u128;
        digits += 1;
    }
    digits
}

/// The base of Halton dimension `dim`, or `None` if `dim >= NUM_DIMENSIONS`.
#[inline]
pub fn prime(dim: u32) -> Option<u32> {
    PRIMES.get(dim as usize).copied()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Brute-force primality, independent of the sieve above.
    fn is_prime(n: u32) -> bool {
        n >= 2 && (2..n).take_while(|d| d * d <= n).all(|d| n % d != 0)
    }

    #[test]
    fn table_holds_exactly_the_first_primes() {
        let brute: alloc::vec::Vec<u32> = (2..)
            .filter(|&n| is_prime(n))
            .take(NUM_DIMENSIONS as usize)
            .collect();
        assert_eq!(&PRIMES[..], &brute[..]);
        // Well-known values: the 1000th prime is 7919, the 1024th 8161, the
        // largest below 2^16 65521.
        assert_eq!(PRIMES[999], 7919);
        assert_eq!(PRIMES[1023], 8161);
        assert_eq!(PRIMES[NUM_DIMENSIONS as usize - 1], 65521);
        assert_eq!(prime(0), Some(2));
        assert_eq!(prime(NUM_DIMENSIONS), None);
    }

    #[test]
    fn digit_counts_cover_64_bits() {
        assert_eq!(scrambled_digits(2), 64);
        assert_eq!(scrambled_digits(3), 41); // 3^40 < 2^64 <= 3^41
        assert_eq!(scrambled_digits(8161), 5);
        for &b in PRIMES.iter() {
            let k = scrambled_digits(b);
            let full = (b as u128).pow(k);
            let less = (b as u128).pow(k - 1);
            assert!(full >= 1 << 64 && less < 1 << 64, "base {b}");
        }
    }
}
