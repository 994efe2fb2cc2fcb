package rp1.planparser;

/**
 * The numbers of one numeric list, as written (not yet converted to metres).
 *
 * @param values the numbers, signs applied
 * @param tokens the number token of each value, where an error in that value is reported
 * @param end the {@code ;} or {@code }} that ended the list, where count errors are reported (the
 *     original reported them on that line too)
 */
record NumberList(double[] values, Token[] tokens, Token end) {
}
