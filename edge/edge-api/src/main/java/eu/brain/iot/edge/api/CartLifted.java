package eu.brain.iot.edge.api;

/** A robot lifted a cart (corkscrew motion) and now carries it. */
public class CartLifted extends RobotEvent {

    public String cartId;
    public int x;
    public int y;
}
