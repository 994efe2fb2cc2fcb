package rp1.simulator.batch;

/** {@link HogDlc} placed at "yard" (and named so): a second robot in the same run. */
public class YardDlc extends HogDlc {
    @Override
    String placement() {
        return "yard";
    }
}
