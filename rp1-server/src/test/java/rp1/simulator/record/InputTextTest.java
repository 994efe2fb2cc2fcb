package rp1.simulator.record;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.Color;
import java.util.List;

import org.junit.jupiter.api.Test;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsBodyPart;
import rp1.rossum.RsDifferentialSteering;
import rp1.rossum.request.RsMotionRequest;
import rp1.simulator.ViewAction;
import rp1.simulator.session.Request;

/** Inputs in a recording's text come back as they were: every kind, every value to the last bit. */
class InputTextTest {

    private static String written(Request r) {
        TextLine line = new TextLine("input");
        InputText.write(line, r);
        return line.toString();
    }

    private static Request readBack(String line) throws RecordingException {
        LineCursor in = new LineCursor("test", 1, line);
        in.word("keyword");
        Request r = InputText.readRequest(in);
        in.end();
        return r;
    }

    @Test
    void everyKindOfRequestReadsBackToTheSameText() throws Exception {
        List<Request> requests = List.of(
                new Request.Timeout(-0.5, 3),
                new Request.Subscription(6, 12, true),
                new Request.SensorStatus(42),
                new Request.Motion(new RsMotionRequest(0.1 + 0.2, -1.0e-300, 3.0)),
                new Request.ActuatorControl(5, 1, new String[] {"left", null}, new double[] {0.3, -Double.MAX_VALUE}),
                new Request.Halt(),
                new Request.Position(),
                new Request.Placement("home \"quoted\" \\ é\n\u0001"),
                new Request.TargetSelection(true, "", false, true),
                new Request.Plan(),
                new Request.Heartbeat(0.25),
                new Request.PainterChange(6, false, true, true, 0.1, -0.0, 0.02,
                        new Color[] {new Color(1, 2, 3), new Color(10, 20, 30, 40), null}),
                new Request.PainterChange(6, true, false, false, 0.0, 0.0, 0.0, null),
                new Request.EncoderStatus(2, new int[] {7, 8}, true),
                new Request.Departure());
        for (Request r : requests) {
            String text = written(r);
            assertEquals(text, written(readBack(text)), "read back: " + text);
        }
    }

    @Test
    void numbersComeBackBitForBit() throws Exception {
        double v = 0.1 + 0.2;
        Request.Motion m = (Request.Motion) readBack(written(new Request.Motion(new RsMotionRequest(v, -0.0, 1e-300))));
        assertEquals(Double.doubleToRawLongBits(v), Double.doubleToRawLongBits(m.motion().linearVelocity));
        assertEquals(Double.doubleToRawLongBits(-0.0), Double.doubleToRawLongBits(m.motion().rotationalVelocity));
        assertEquals(1e-300, m.motion().duration);
    }

    @Test
    void aBodyComesBackWithThePartIdsItHadInTheRun() throws Exception {
        RsBody body = new RsBody("wheeled");
        body.addPart(new RsBodyCircle(0.0, 0.0, 0.15));
        RsDifferentialSteering drive = new RsDifferentialSteering(0.18, 0.075);
        drive.addDefaultWheels(0.075, 0.03);
        body.addPart(drive);
        String text = written(new Request.Body(body));
        // A part made in between must not change the ids read back.
        new RsBodyCircle(0.0, 0.0, 0.1);
        RsBody back = ((Request.Body) readBack(text)).body();
        assertEquals("wheeled", back.getName());
        assertEquals(ids(body), ids(back));
        assertEquals(4, ids(back).split(" ").length, "the circle, the drive and its two wheels");
    }

    private static String ids(RsBody body) {
        StringBuilder b = new StringBuilder();
        for (RsBodyPart p : body.getBodyPartArray()) {
            b.append(p.getID()).append(' ');
            if (p instanceof RsDifferentialSteering d) {
                for (RsBodyPart w : d.getPartsArray()) {
                    b.append(w.getID()).append(' ');
                }
            }
        }
        return b.toString();
    }

    @Test
    void viewActionsReadBackAsTheyWere() throws Exception {
        for (ViewAction a : List.of(new ViewAction.MouseClick(3, 2, -1.5, 2.25), new ViewAction.RemovePaintTrails())) {
            TextLine line = new TextLine("input");
            InputText.write(line, a);
            LineCursor in = new LineCursor("test", 1, line.toString());
            in.word("keyword");
            assertEquals(a, InputText.readViewAction(in));
        }
    }
}
