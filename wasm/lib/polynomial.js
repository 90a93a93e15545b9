// An axis polynomial's value (Eq. 12): coefficients a0..an at the motion parameter t, by Horner's rule.
export const polynomialAt = (coefficients, t) => coefficients.reduceRight((acc, a) => acc * t + a, 0);
