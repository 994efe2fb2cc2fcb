/**
 * ClientZero, the original user's guide's example client (docs/guide.md section 2): a round robot with a target sensor
 * ("head") at its front that goes where the user clicks. {@link rp1demo.clientzero.ClnMain} is the
 * simulator interface (it extends {@code RsClient}; one handler class per event, as in the guide);
 * {@link rp1demo.clientzero.ClnNavigator} is the little robot logic behind it;
 * {@link rp1demo.clientzero.ClientZero#build()} is the body plan of the guide's Figure 9.
 */
package rp1demo.clientzero;
