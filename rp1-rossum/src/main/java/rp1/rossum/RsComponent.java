package rp1.rossum;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.io.Serializable;

/**
 * Base of the body model ({@link RsBody}, every {@link RsBodyPart}, motions). Its {@link #clone()} is
 * deep: a cloned body shares no mutable state with the original, which is what the simulator needs
 * to hand a consistent copy of a robot to an observer.
 */
public abstract class RsComponent implements Serializable, Cloneable {
    private static final long serialVersionUID = 1L;

    /** A component; subclasses hold the state. */
    public RsComponent() {
    }

    /** A deep copy, made by serialization. */
    @Override
    public Object clone() throws CloneNotSupportedException {
        try {
            ByteArrayOutputStream bytes = new ByteArrayOutputStream();
            try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
                out.writeObject(this);
            }
            try (ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(bytes.toByteArray()))) {
                return in.readObject();
            }
        } catch (IOException | ClassNotFoundException e) {
            CloneNotSupportedException c = new CloneNotSupportedException("deep copy of " + getClass().getName() + " failed: " + e);
            c.initCause(e);
            throw c;
        }
    }
}
