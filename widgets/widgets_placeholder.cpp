namespace mx::widgets {}
