package eu.brain.iot.behaviours.warehouse;

/** A grid cell: column {@code x} from the left, row {@code y} from the top (north is y - 1). */
public record Cell(int x, int y) {

    /** @return the cell one step in a direction {@code N}, {@code E}, {@code S} or {@code W} (else this cell) */
    public Cell toward(String heading) {
        return switch (heading == null ? "" : heading) {
            case "N" -> new Cell(x, y - 1);
            case "E" -> new Cell(x + 1, y);
            case "S" -> new Cell(x, y + 1);
            case "W" -> new Cell(x - 1, y);
            default -> this;
        };
    }

    /** @return the Manhattan distance to another cell */
    public int distance(Cell other) {
        return Math.abs(x - other.x) + Math.abs(y - other.y);
    }

    @Override
    public String toString() {
        return "(" + x + "," + y + ")";
    }
}
